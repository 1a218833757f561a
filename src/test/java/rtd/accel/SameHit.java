package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import rtd.geometry.Hit;

/** The check of the tests that a faster path finds the paper's loop's hit: the same object, t, distance and point, to the last bit. */
final class SameHit {

    private SameHit() {
    }

    static void assertSame(Hit actual, Hit expected, String what) {
        if (expected == null) {
            assertThat(actual).as(what).isNull();
            return;
        }
        assertThat(actual).as(what).isNotNull();
        assertThat(actual.index()).as(what + ": object").isEqualTo(expected.index());
        assertThat(Float.floatToIntBits(actual.t())).as(what + ": t").isEqualTo(Float.floatToIntBits(expected.t()));
        assertThat(actual.distance()).as(what + ": distance").isEqualTo(expected.distance());
        assertThat(actual.point()).as(what + ": point").isEqualTo(expected.point());
    }
}
