package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.math.Vector3f;

@DisplayName("A shape's box")
class BoundingBoxTest {

    @Test
    void aPointsBoxIsThePointGrownByTheMarginAndRoundedOutwards() {
        BoundingBox box = BoundingBox.around(0.5, new Vector3f(1, -2, 0));

        // grown by 0.5·(1 + 1e-6) and 8u·2 (2 the largest coordinate), then one float further out
        double grow = 0.5 * (1 + 1e-6) + 8 * 0x1p-24 * 2;
        assertThat(box.min()).isEqualTo(new Vector3f(Math.nextDown((float) (1 - grow)),
                Math.nextDown((float) (-2 - grow)), Math.nextDown((float) -grow)));
        assertThat(box.max()).isEqualTo(new Vector3f(Math.nextUp((float) (1 + grow)), Math.nextUp((float) (-2 + grow)),
                Math.nextUp((float) grow)));
    }

    @Test
    void theBoxOfPointsInAnArrayIsTheBoxAroundThemToTheLastBit() {
        Random random = new Random(19);
        for (int i = 0; i < 10_000; i++) {
            int count = 1 + random.nextInt(4);
            float scale = (float) Math.pow(10, random.nextInt(13) - 6);
            float[] points = new float[2 + 3 * count];
            Vector3f[] vectors = new Vector3f[count];
            for (int p = 0; p < count; p++) {
                vectors[p] = new Vector3f(coordinate(random, scale), coordinate(random, scale), coordinate(random, scale));
                points[2 + 3 * p] = vectors[p].x();
                points[3 + 3 * p] = vectors[p].y();
                points[4 + 3 * p] = vectors[p].z();
            }
            double margin = random.nextInt(3) == 0 ? 0 : random.nextDouble() * scale;
            float[] written = new float[7];
            BoundingBox.putAround(margin, points, 2, count, written, 1);
            float[] expected = new float[7];
            BoundingBox.around(margin, vectors).put(expected, 1);
            assertThat(written).isEqualTo(expected);
        }
    }

    /** Any coordinate of about {@code scale}, now and then −0. */
    private static float coordinate(Random random, float scale) {
        return random.nextInt(10) == 0 ? -0f : (random.nextFloat() - 0.5f) * scale;
    }
}
