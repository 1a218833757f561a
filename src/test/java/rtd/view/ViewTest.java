package rtd.view;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.BitSet;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Supplier;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.accel.Bvh;
import rtd.geometry.Hit;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.image.Picture;
import rtd.math.Ray;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.render.Tracer;
import rtd.scene.Scene;
import rtd.shade.FlatShader;
import rtd.testing.MixedScenes;
import rtd.testing.RandomScenes;
import rtd.testing.Scenes;

@DisplayName("The views of what the rays did")
class ViewTest {

    private static RenderResult render(Scene scene, View view, Supplier<Tracer> tracers, int threads) {
        ViewShader shader = new ViewShader(view, scene.objects());
        return ParallelRenderer.render(scene.camera(), tracers, tracer -> shader, 64, 48, 1, threads, new RenderProgress());
    }

    private static long sum(int[] counts) {
        long sum = 0;
        for (int count : counts) {
            sum += count;
        }
        return sum;
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 3, 4})
    void theCostViewsCountsSumToTheRendersIntersectionTestsWithTheLoopAndWithTheBvh(long seed) {
        for (Scene scene : List.of(RandomScenes.generate(seed, 200), MixedScenes.generate(seed, 200))) { // beams, and single rays with planes
            FlatShader flat = new FlatShader(scene);
            Bvh bvh = Bvh.build(scene);
            for (Supplier<Tracer> tracers : List.<Supplier<Tracer>>of(bvh::newTracer, () -> new LinearTracer(scene))) {
                RenderResult cost = render(scene, View.cost, tracers, 2);
                RenderResult picture = ParallelRenderer.render(scene.camera(), tracers, tracer -> flat, 64, 48, 1, 3,
                        new RenderProgress());
                assertThat(sum(cost.image().rgb())).isEqualTo(cost.work().intersectionTests())
                        .isEqualTo(picture.work().intersectionTests());
            }
        }
    }

    @Test
    void withThePapersLoopEveryRayTakesATestOfEveryObject() {
        Scene scene = RandomScenes.generate(9, 123);
        int[] counts = render(scene, View.cost, () -> new LinearTracer(scene), 1).image().rgb();
        assertThat(counts).containsOnly(123);
    }

    @Test
    void theBvhTakesFarFewerTestsThanTheLoopOnAThousandSpheres() {
        Scene scene = RandomScenes.generate(5, 1000);
        int[] counts = render(scene, View.cost, Bvh.build(scene)::newTracer, 2).image().rgb();
        assertThat((double) sum(counts) / counts.length).isLessThan(100);
    }

    @Test
    void theCostPictureHasItsScaleInAStripBelowAndInWords() {
        Scene scene = RandomScenes.generate(5, 100);
        RenderResult raw = render(scene, View.cost, Bvh.build(scene)::newTracer, 1);
        ViewPicture view = ViewPicture.of(View.cost, raw.image(), scene);
        assertThat(view.picture().width()).isEqualTo(64);
        assertThat(view.picture().height()).isEqualTo(48 + Legend.HEIGHT);
        assertThat(view.report()).contains("logarithmic scale from 0 (black) to 100", "tests for 3,072 rays");
        int barLeft = view.picture().rgb(8, 48 + 8);
        int barRight = view.picture().rgb(64 - 9, 48 + 8);
        assertThat(barLeft).isEqualTo(ViewColours.heat(0));
        assertThat(barRight).isEqualTo(ViewColours.heat(1));
    }

    @Test
    void distinctObjectsGetDistinctColoursAndNoneIsTheBackgroundsBlack() {
        BitSet colours = new BitSet(1 << 24);
        colours.set(0); // the background
        for (int i = 0; i < (1 << 24) - 1; i++) { // every object a scene can have a colour for
            int colour = ViewColours.id(i);
            assertThat(colours.get(colour)).as("object %d", i).isFalse();
            colours.set(colour);
        }
        assertThat(ViewColours.id(-1)).isZero();
    }

    @Test
    void theIdViewPaintsEachPixelInTheColourOfTheObjectTheLoopFinds() {
        Scene scene = MixedScenes.generate(4, 50);
        int[] ids = render(scene, View.id, Bvh.build(scene)::newTracer, 2).image().rgb();
        Set<Integer> seen = new HashSet<>();
        for (int y = 0; y < 48; y++) {
            for (int x = 0; x < 64; x++) {
                Hit hit = scene.nearestHit(scene.camera().generateRay(x, y, 64, 48));
                assertThat(ids[y * 64 + x]).isEqualTo(ViewColours.id(hit == null ? -1 : hit.index()));
                seen.add(hit == null ? -1 : hit.index());
            }
        }
        assertThat(seen).hasSizeGreaterThan(3);
    }

    @Test
    void theDepthViewIsBrightNearDarkerFarAndBlackWhereNothingIsHit() {
        // A sphere of radius 2 at the origin seen from z = 20 at 10 pixels a unit: its middle is nearest.
        Scene scene = new Scene(Color.BLACK, Scenes.frontCamera(20, 10),
                List.of(new Sphere(new Vector3f(0, 0, 0), 2, new Color(255, 0, 0))));
        Picture raw = render(scene, View.depth, Bvh.build(scene)::newTracer, 1).image();
        ViewPicture depth = ViewPicture.of(View.depth, raw, scene);
        assertThat(grey(depth.picture(), 32, 24)).isEqualTo(255);
        assertThat(grey(depth.picture(), 32 + 18, 24)).isBetween(1, 254);
        assertThat(grey(depth.picture(), 0, 0)).isZero();
        assertThat(depth.report()).contains("white at 18.00", "no hit: black");
    }

    /**
     * Ten hits at 1 to 9 and 1000 units (an open floor's horizon): the farthest lies more than
     * twice as far as 90 % of them, so the scale runs from 1 to 9 (hits[8] of the ten sorted):
     * 5 is half way, grey 255 − 0.5·(255 − 48) = 151.5, rounded 152; 1000 is dark grey too.
     * Without the far hit, at 1 to 10, the scale runs to the farthest.
     */
    @Test
    void theDepthScaleEndsAtNinetyPercentOfTheHitsWhenTheFarthestLieFarBeyond() {
        Scene empty = new Scene(Color.BLACK, Scenes.frontCamera(20, 10), List.of());
        ViewPicture depth = ViewPicture.of(View.depth, distances(1, 2, 3, 4, 5, 6, 7, 8, 9, 1000), empty);
        assertThat(grey(depth.picture(), 0, 0)).isEqualTo(255);
        assertThat(grey(depth.picture(), 4, 0)).isEqualTo(152);
        assertThat(grey(depth.picture(), 8, 0)).isEqualTo(48);
        assertThat(grey(depth.picture(), 9, 0)).isEqualTo(48);
        assertThat(depth.report()).contains("dark grey at 9.000, which 90 % of the hits are nearer than (the farthest, at 1000,");
        ViewPicture closed = ViewPicture.of(View.depth, distances(1, 2, 3, 4, 5, 6, 7, 8, 9, 10), empty);
        assertThat(grey(closed.picture(), 9, 0)).isEqualTo(48);
        assertThat(grey(closed.picture(), 8, 0)).isEqualTo(71); // 255 − (8/9)·207 = 71
        assertThat(closed.report()).contains("dark grey at 10.00 (the farthest)");
    }

    private static Picture distances(float... distances) {
        int[] raw = new int[distances.length];
        for (int i = 0; i < raw.length; i++) {
            raw[i] = Float.floatToRawIntBits(distances[i]);
        }
        return new Picture(raw.length, 1, raw);
    }

    @Test
    void theNormalViewShowsTheNormalAsColour() {
        Scene scene = Scenes.example("input_rtd");
        Ray ray = scene.camera().generateRay(460, 490, 1920, 1080);
        Hit hit = scene.nearestHit(ray); // the red sphere's nearest point: normal (0, 0, 1)
        assertThat(ViewShader.normalColour(hit, ray)).isEqualTo(0x8080FF);
        assertThat(ViewShader.normalColour(null, ray)).isZero();
    }

    private static int grey(Picture picture, int x, int y) {
        return picture.rgb(x, y) & 0xFF;
    }
}
