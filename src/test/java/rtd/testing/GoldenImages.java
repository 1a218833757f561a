package rtd.testing;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * Golden-image checks: compares a rendered image with the committed expected image under
 * {@code src/test/resources/golden}. On a mismatch it writes the actual image and a diff under
 * {@code target/golden-failures} and names them. With {@code -Dgolden.update=true} it writes
 * the actual image as the new golden instead; a missing golden fails.
 */
public final class GoldenImages {

    /** Where the goldens live in the source tree (Surefire runs in the project folder). */
    public static final Path GOLDEN_DIR = Path.of("src", "test", "resources", "golden");
    /** Where a failed comparison leaves its images. */
    public static final Path FAILURE_DIR = Path.of("target", "golden-failures");

    private GoldenImages() {
    }

    /** Whether this run regenerates goldens ({@code mvn verify -Dgolden.update=true}). */
    public static boolean updating() {
        return Boolean.getBoolean("golden.update");
    }

    /** Asserts that {@code actual} matches golden {@code name}.png by {@code rule}. */
    public static void assertMatchesGolden(String name, BufferedImage actual, ImageComparison rule) {
        Path golden = GOLDEN_DIR.resolve(name + ".png");
        try {
            if (updating()) {
                Files.createDirectories(GOLDEN_DIR);
                ImageIO.write(actual, "png", golden.toFile());
                assertThat(golden).exists();
                return;
            }
            if (!Files.exists(golden)) {
                fail("missing golden image " + golden + "; create it with mvn verify -Dgolden.update=true, "
                        + "then look at it before committing it");
            }
            BufferedImage expected = ImageIO.read(golden.toFile());
            ImageComparison.Result result = rule.compare(expected, actual);
            if (!result.matches()) {
                Files.createDirectories(FAILURE_DIR);
                Path actualFile = FAILURE_DIR.resolve(name + "-actual.png");
                Path diffFile = FAILURE_DIR.resolve(name + "-diff.png");
                ImageIO.write(actual, "png", actualFile.toFile());
                if (result.diff() != null) {
                    ImageIO.write(result.diff(), "png", diffFile.toFile());
                }
                fail("image differs from golden " + golden + ": " + result.summary()
                        + "; actual: " + actualFile + ", diff (red = wrong, yellow = tolerated): " + diffFile);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
