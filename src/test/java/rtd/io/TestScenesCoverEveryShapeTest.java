package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.IGeometry;
import rtd.testing.MixedScenes;
import rtd.testing.Scenes;

/**
 * The render paths' tests (the BVH and the grids against the paper's loop, the explained steps,
 * shading on every path, POV-Ray's twin) draw their objects from {@link MixedScenes}: a shape it
 * never makes would pass them all untested. So every statement of the grammar that makes an
 * object must show up in its scenes, by its kind; a mesh as the triangles it is made of.
 */
@DisplayName("The random scenes of the tests")
class TestScenesCoverEveryShapeTest {

    @Test
    void holdEveryShapeTheGrammarMakes() {
        Set<String> kinds = new HashSet<>();
        for (long seed = 1; seed <= 4; seed++) {
            for (IGeometry object : MixedScenes.generate(seed, 60).objects()) {
                kinds.add(object.kind());
            }
        }
        for (Statement statement : Grammar.STATEMENTS) {
            if (statement.takesMaterial()) {
                String kind = statement.keyword().equals("mesh") ? "triangle" : statement.keyword();
                assertThat(kinds).as("MixedScenes makes no %s: add it to LATER and twin", kind).contains(kind);
            }
        }
    }

    @Test
    void andTheCommandLinesSceneOfEveryShapeHoldsEachOnce() {
        for (Statement statement : Grammar.STATEMENTS) {
            if (statement.takesMaterial()) {
                assertThat(Scenes.EVERY_SHAPE.lines().filter(line -> line.startsWith(statement.keyword() + ":(")))
                        .as("rtd.testing.Scenes.EVERY_SHAPE has no line of %s: add one, patterned and transformed",
                                statement.keyword()).hasSize(1);
            }
        }
    }
}
