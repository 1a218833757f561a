package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.testing.Cli;
import rtd.testing.Cli.Run;

/** {@code --export-pov FILE.pov}: the export beside the picture, under the rules of {@code -o}. */
@DisplayName("--export-pov on the command line")
class PovExportTest {

    private static final Path EXAMPLE = Path.of("examples", "input_rtd.txt");

    @TempDir
    Path dir;

    private Run export(String... more) {
        String[] args = new String[more.length + 5];
        args[0] = EXAMPLE.toString();
        args[1] = "--width";
        args[2] = "64";
        args[3] = "--height";
        args[4] = "36";
        System.arraycopy(more, 0, args, 5, more.length);
        return Cli.run(args);
    }

    @Test
    void writesTheSceneForPovRayAndThePictureToo() throws IOException {
        Path pov = dir.resolve("paper.pov");
        Run run = export("--export-pov", pov.toString(), "-o", dir.resolve("paper.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(Files.readString(pov)).startsWith("// A POV-Ray 3.7 twin of an rtd scene");
        assertThat(run.err()).contains("wrote " + pov, "povray +Ipaper.pov");
        assertThat(dir.resolve("paper.png")).isRegularFile();
    }

    /** A name of 249 bytes, near most file systems' 255: the export's temporary file must be named shorter. */
    @Test
    void aLongNameIsWrittenAsALongPictureNameIsAndNoTemporaryFileStays() throws IOException {
        Path pov = dir.resolve("a".repeat(245) + ".pov");
        Run run = export("--export-pov", pov.toString(), "-o", dir.resolve("p.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(Files.readString(pov)).startsWith("// A POV-Ray 3.7 twin of an rtd scene");
        try (var files = Files.list(dir)) {
            assertThat(files.map(f -> f.getFileName().toString())).allMatch(name -> !name.endsWith(".tmp"));
        }
    }

    @Test
    void aNameThatDoesNotEndInPovIsRefusedSoThatAMeshOrAFolderIsNeverReplaced() throws IOException {
        Path mesh = Files.writeString(dir.resolve("model.obj"), "v 0 0 0\n");
        Path folder = Files.createDirectory(dir.resolve("renders"));
        for (Path named : new Path[] {mesh, folder}) {
            Run run = export("--export-pov", named.toString(), "-o", dir.resolve("p.png").toString());
            assertThat(run.exitCode()).as(run.err()).isEqualTo(2);
            assertThat(run.err()).contains("its name must end in .pov");
        }
        assertThat(Files.readString(mesh)).isEqualTo("v 0 0 0\n");
        assertThat(folder).isDirectory();
        assertThat(dir.resolve("p.png")).doesNotExist();
    }

    @Test
    void aFolderNamedLikeAnExportIsRefusedAndStays() throws IOException {
        Path folder = Files.createDirectory(dir.resolve("old.pov"));
        Run run = export("--export-pov", folder.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("is a folder");
        assertThat(folder).isDirectory();
    }

    @Test
    void theSceneFileItselfIsRefused() throws IOException {
        Path scene = Files.copy(EXAMPLE, dir.resolve("scene.pov"));
        Run run = Cli.run(scene.toString(), "--export-pov", scene.toString(), "--width", "64", "--height", "36");
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("is the scene file itself; choose another with --export-pov");
        assertThat(Files.readString(scene)).isEqualTo(Files.readString(EXAMPLE));
    }

    @Test
    void aMissingFolderIsAFileErrorAndNothingIsWritten() {
        Run run = export("--export-pov", dir.resolve("nope").resolve("x.pov").toString(), "-o", dir.resolve("p.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("cannot write", "does not exist");
        assertThat(dir.resolve("p.png")).doesNotExist();
    }

    @Test
    void noExportIsWrittenWhenThePictureCannotBe() {
        Path pov = dir.resolve("x.pov");
        Run run = export("--export-pov", pov.toString(), "-o", dir.resolve("nope").resolve("p.png").toString());
        assertThat(run.exitCode()).isEqualTo(1);
        assertThat(run.err()).contains("the folder").doesNotContain("wrote");
        assertThat(pov).doesNotExist();
    }

    @Test
    void aLinkToAnExportIsFollowedAndStaysALink() throws IOException {
        Path real = Files.writeString(dir.resolve("real.pov"), "old\n");
        Path link = Files.createSymbolicLink(dir.resolve("link.pov"), real.getFileName());
        Run run = export("--export-pov", link.toString(), "-o", dir.resolve("p.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(Files.isSymbolicLink(link)).isTrue();
        assertThat(Files.readString(real)).startsWith("// A POV-Ray 3.7 twin");
    }

    @Test
    void aNameEndingInASlashNamesAFolderAndIsRefusedForTheExportAndThePicture() throws IOException {
        Path keep = Files.writeString(dir.resolve("keep.png"), "keep");
        for (String[] args : new String[][] {{"-o", keep + "/"}, {"--export-pov", dir.resolve("new") + "/"}}) {
            Run run = export(args);
            assertThat(run.exitCode()).as(run.err()).isEqualTo(2);
            assertThat(run.err()).contains("so it names a folder, not a file");
        }
        assertThat(Files.readString(keep)).isEqualTo("keep");
        assertThat(dir.resolve("new")).doesNotExist();
    }

    @Test
    void aLinkNamedPovToAnotherKindOfFileIsRefusedAndTheFileStays() throws IOException {
        Path mesh = Files.writeString(dir.resolve("keep.obj"), "v 0 0 0\n");
        Path link = Files.createSymbolicLink(dir.resolve("link.pov"), mesh.getFileName());
        Run run = export("--export-pov", link.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("whose name does not end in .pov");
        assertThat(Files.readString(mesh)).isEqualTo("v 0 0 0\n");
    }

    @Test
    void aMistakeInTheExportsNameIsNamedBeforeAProblemWithThePicturesFile() {
        Run run = export("--export-pov", dir.resolve("x.obj").toString(), "-o", dir.resolve("nope").resolve("p.png").toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).contains("its name must end in .pov");
    }

    @Test
    void anImageTooLargeIsMisuseBeforeTheExportIsWritten() {
        Path pov = dir.resolve("big.pov");
        Run run = Cli.run(EXAMPLE.toString(), "--width", "60000", "--height", "60000", "--export-pov", pov.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(pov).doesNotExist();
    }

    @Test
    void thePrintedCommandQuotesANameWithSpacesForTheShellAndForPovRay() throws IOException {
        Path folder = Files.createDirectory(dir.resolve("my renders"));
        Run run = export("--export-pov", folder.resolve("a b.pov").toString(), "-o", dir.resolve("p.png").toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).contains("cd '" + folder.toAbsolutePath() + "' && povray '+I\"a b.pov\"' '+O\"a b-pov.png\"'");
    }

    @Test
    void standardOutputAndANameWithADoubleQuoteAreMisuse() {
        Run dash = export("--export-pov", "-");
        assertThat(dash.exitCode()).isEqualTo(2);
        assertThat(dash.err()).contains("--export-pov writes a file, not standard output ('-')");
        Run quote = export("--export-pov", dir.resolve("a\"b.pov").toString());
        assertThat(quote.exitCode()).isEqualTo(2);
        assertThat(quote.err()).contains("a name with a double quote cannot be given to POV-Ray");
    }

    @Test
    void theExportIsAPhaseOfItsOwnInTheStatistics() {
        Run run = export("--export-pov", dir.resolve("s.pov").toString(), "-o", dir.resolve("s.png").toString(), "--stats");
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.err()).containsPattern("export +[0-9.]+ s  the scene for POV-Ray");
    }
}
