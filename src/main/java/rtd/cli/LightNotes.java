package rtd.cli;

import java.util.ArrayList;
import java.util.List;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Rgb;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * Two slips with light that draw a picture without a word of why it looks wrong: a light so dim
 * it is nearly black, as a light of {@code (1|1|1)} is when written as <i>The Ray Tracer
 * Challenge</i> writes full white (rtd's colours run to 255); and materials in a scene without
 * any light, which is drawn in the paper's flat colours, so that the materials do nothing.
 */
final class LightNotes {

    /**
     * The most objects looked at for a material: a student's scene, in a millisecond or two. A
     * million objects, scattered in memory, take 15 ms to visit (measured), more than a note is worth.
     */
    private static final int MOST_LOOKED_AT = 100_000;
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
        if (lights.isEmpty() && scene.objects().size() <= MOST_LOOKED_AT && anyMaterial(scene.objects())) {
            notes.add("rtd: note: " + name + ": objects have materials, but the scene has no light, so it is drawn in "
                    + "flat colours, as in the paper; add a light: statement to see the materials");
        }
        return notes;
    }

    private static boolean anyMaterial(List<IGeometry> objects) {
        // a loop over a million objects, comparing references: an object that names no material has
        // Material.DEFAULT itself, and a record's equals would cost its first call's setting up on every run
        for (int i = 0, n = objects.size(); i < n; i++) {
            if (objects.get(i).material() != Material.DEFAULT) {
                return true;
            }
        }
        return false;
    }

    private static long level(float channel) {
        return Math.round(channel * 255);
    }
}
