package rtd.cli;

import java.util.ArrayList;
import java.util.List;
import rtd.image.Rgb;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * A slip with light that draws a picture without a word of why it looks wrong: a light so dim
 * it is nearly black, as a light of {@code (1|1|1)} is when written as <i>The Ray Tracer
 * Challenge</i> writes full white (rtd's colours run to 255). (Materials in a scene without a
 * light are told by the reader, at the material's line: {@code rtd.io.MaterialWarnings}.)
 */
final class LightNotes {

    /** One level of 255: a light no brighter than this in every channel is all but black. */
    private static final float ONE_LEVEL = 1 / 255f;

    private LightNotes() {
    }

    /** The lines to print for {@code scene}, named {@code name}: none for most scenes. */
    static List<String> of(String name, Scene scene) {
        List<String> notes = new ArrayList<>();
        List<Light> lights = scene.lights();
        for (int i = 0; i < lights.size(); i++) {
            Rgb c = lights.get(i).intensity();
            float brightest = Math.max(c.red(), Math.max(c.green(), c.blue()));
            if (brightest > 0 && brightest <= ONE_LEVEL) {
                notes.add("rtd: warning: " + name + ": light #" + (i + 1) + " has the intensity "
                        + "(" + level(c.red()) + "|" + level(c.green()) + "|" + level(c.blue()) + "), almost black: "
                        + "rtd's colours run from 0 to 255, so a full white light is (255|255|255)");
            }
        }
        return notes;
    }

    private static long level(float channel) {
        return Math.round(channel * 255);
    }
}
