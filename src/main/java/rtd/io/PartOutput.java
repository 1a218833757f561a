package rtd.io;

import java.util.List;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.scene.Light;

/**
 * Hands what a statement makes to the part, with the statement's place where a later check needs it:
 * the {@link Statement.Output} of a {@link StatementReader}.
 */
final class PartOutput implements Statement.Output {

    private final StatementReader reader;
    private final ScenePart part;
    private final GroupValues values;

    /** An output into {@code part}, for the statements {@code reader} reads into {@code values}. */
    PartOutput(StatementReader reader, ScenePart part, GroupValues values) {
        this.reader = reader;
        this.part = part;
        this.values = values;
    }

    @Override
    public void ambient(Color colour) {
        part.ambients.add(new ScenePart.Located<>(colour, reader.located()));
    }

    @Override
    public void camera(ICamera camera) {
        part.cameras.add(new ScenePart.Located<>(camera, reader.located()));
    }

    @Override
    public void light(Light light) {
        part.lights.add(light);
    }

    @Override
    public void object(IGeometry object) {
        part.objects.add(object);
    }

    @Override
    public void objects(List<IGeometry> objects) {
        part.objects.addAll(objects);
    }

    @Override
    public void material(String name, Material material) {
        part.materials.add(new ScenePart.Located<>(new ScenePart.Named(name, material), values.placeOfValue(0, 0)));
    }
}
