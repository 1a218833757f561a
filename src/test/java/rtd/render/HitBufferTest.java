package rtd.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("The hit buffer, answered ray by ray or for a whole bundle at once")
class HitBufferTest {

    private static final Ray RAY = new Ray(new Vector3f(0, 0, 0), new Vector3f(0, 0, 1));

    @Test
    void afterEveryRayMissedEachEntryReadsAsAMissWithoutATest() {
        HitBuffer hits = new HitBuffer(8);
        for (int i = 0; i < 8; i++) {
            hits.set(i, 3, 1f, 2f);
            hits.setTests(i, 5);
        }

        hits.setMisses(6);

        assertThat(hits.missedAll()).isTrue();
        for (int i = 0; i < 6; i++) {
            assertThat(hits.index(i)).isEqualTo(-1);
            assertThat(hits.distance(i)).isEqualTo(Float.POSITIVE_INFINITY);
            assertThat(hits.tests(i)).isZero();
            assertThat(hits.hit(i, RAY, List.<IGeometry>of())).isNull();
        }
    }

    @Test
    void oneRaySetAfterAllMissedLeavesTheOthersMisses() {
        HitBuffer hits = new HitBuffer(4);
        for (int i = 0; i < 4; i++) {
            hits.set(i, 2, 7f, 7f);
        }
        hits.setMisses(4);

        hits.set(2, 1, 3f, 4f);
        hits.setTests(2, 9);

        assertThat(hits.missedAll()).isFalse();
        assertThat(new int[] {hits.index(0), hits.index(1), hits.index(2), hits.index(3)}).containsExactly(-1, -1, 1,
                -1);
        Sphere sphere = new Sphere(new Vector3f(0, 0, 5), 1, new Color(1, 2, 3));
        assertThat(hits.hit(2, RAY, List.of(sphere, sphere)).t()).isEqualTo(3f);
        assertThat(hits.distance(2)).isEqualTo(4f);
        assertThat(hits.distance(3)).isEqualTo(Float.POSITIVE_INFINITY);
        assertThat(new int[] {hits.tests(0), hits.tests(2)}).containsExactly(0, 9);
    }

    @Test
    void testsCountedAfterEveryRayMissedKeepTheOthersAtNone() {
        HitBuffer hits = new HitBuffer(3);
        hits.setMisses(3);

        hits.setTests(0, 2);

        assertThat(new int[] {hits.tests(0), hits.tests(1), hits.tests(2)}).containsExactly(2, 0, 0);
        assertThat(hits.index(2)).isEqualTo(-1);
    }

    @Test
    void aRunOfRaysSetFromArraysAfterAllMissedReadsTheirEntriesAndLeavesTheOthersMisses() {
        HitBuffer hits = new HitBuffer(5);
        hits.setMisses(5);

        hits.set(1, 2, 3, new int[] {9, 9, 9, 4, -1}, new float[] {0, 0, 0, 2.5f, Float.NaN},
                new float[] {0, 0, 0, 3.5f, Float.POSITIVE_INFINITY}, new int[] {0, 0, 0, 6, 1});

        assertThat(hits.missedAll()).isFalse();
        assertThat(new int[] {hits.index(0), hits.index(1), hits.index(2), hits.index(3)}).containsExactly(-1, 4, -1,
                -1);
        assertThat(new float[] {hits.distance(0), hits.distance(1), hits.distance(2)})
                .containsExactly(Float.POSITIVE_INFINITY, 3.5f, Float.POSITIVE_INFINITY);
        Sphere sphere = new Sphere(new Vector3f(0, 0, 5), 1, new Color(1, 2, 3));
        assertThat(hits.hit(1, RAY, List.of(sphere, sphere, sphere, sphere, sphere)).t()).isEqualTo(2.5f);
        assertThat(new int[] {hits.tests(0), hits.tests(1), hits.tests(2), hits.tests(3)}).containsExactly(0, 6, 1, 0);
    }
}
