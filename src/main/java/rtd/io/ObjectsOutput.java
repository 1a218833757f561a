package rtd.io;

import java.util.List;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.scene.Light;

/**
 * Where an object that names a material goes when it is built after the whole file is read:
 * the scene's list of objects. Only objects name a material, so nothing else comes here.
 */
final class ObjectsOutput implements Statement.Output {

    private final List<IGeometry> objects;

    ObjectsOutput(List<IGeometry> objects) {
        this.objects = objects;
    }

    @Override
    public void object(IGeometry object) {
        objects.add(object);
    }

    @Override
    public void objects(List<IGeometry> more) {
        objects.addAll(more);
    }

    @Override
    public void ambient(Color colour) {
        throw onlyObjects();
    }

    @Override
    public void camera(ICamera camera) {
        throw onlyObjects();
    }

    @Override
    public void material(String name, Material material) {
        throw onlyObjects();
    }

    @Override
    public void light(Light light) {
        throw onlyObjects();
    }

    private static IllegalStateException onlyObjects() {
        return new IllegalStateException("only objects name a material");
    }
}
