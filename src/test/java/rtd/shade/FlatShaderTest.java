package rtd.shade;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.scene.Scene;

class FlatShaderTest {

    private static final Scene SCENE = new Scene(new Color(127, 255, 255),
            new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50),
            List.of(new Sphere(new Vector3f(0, 0, 0), 1, new Color(255, 0, 0)),
                    new Sphere(new Vector3f(3, 0, 0), 1, new Color(0, 0, 255))));

    @Test
    void aBundleThatMissedEverythingIsTheBackgroundThroughout() {
        HitBuffer hits = new HitBuffer(4);
        hits.setMisses(3);
        int[] rgb = {1, 2, 3, 4};

        new FlatShader(SCENE).rgbAll(new RayBundle(4), hits, 3, rgb);

        assertThat(rgb).containsExactly(0x7FFFFF, 0x7FFFFF, 0x7FFFFF, 4);
    }

    @Test
    void aBundleWithHitsTakesEachObjectsColourAndTheBackgroundForItsMisses() {
        HitBuffer hits = new HitBuffer(4);
        hits.setMisses(4);
        hits.set(1, 1, 2f, 2f);
        hits.set(3, 0, 5f, 5f);
        int[] rgb = new int[4];

        new FlatShader(SCENE).rgbAll(new RayBundle(4), hits, 4, rgb);

        assertThat(hits.missedAll()).isFalse();
        assertThat(rgb).containsExactly(0x7FFFFF, 0x0000FF, 0x7FFFFF, 0xFF0000);
    }
}
