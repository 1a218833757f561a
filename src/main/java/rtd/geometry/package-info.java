/**
 * The objects of a scene and their intersection tests (section 3.2.2; section 4.2.2): each shape
 * implements {@link rtd.geometry.IGeometry} and tests itself against a ray, the
 * {@link rtd.geometry.Sphere} by equations 3.3 to 3.8; Part II, "Geometry", adds planes, triangles
 * and boxes. Each test is written once, as a static {@code hit} on plain numbers that the shape's
 * {@code intersect}, the engine and {@code --explain} (through a {@link rtd.geometry.TestObserver})
 * all run. A test answers with an {@link rtd.geometry.Intersection}; the depth test that compares
 * objects makes a {@link rtd.geometry.Hit} of the nearest. A new shape goes here: its test, its
 * normal and its box are all every renderer needs. Depends on {@code rtd.math} and {@code rtd.image}.
 */
package rtd.geometry;
