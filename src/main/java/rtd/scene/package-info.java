/**
 * A scene and the paper's algorithm in the paper's shape (Listing 3.1): {@link rtd.scene.Scene}
 * holds the background, the camera, the objects and the lights, and its {@code render} (Listing
 * 4.2), {@code trace} and {@code nearestHit} (Listing 4.3) are the reference that every faster path
 * must equal. {@link rtd.scene.DepthTest} is the depth test's comparison, written once for every
 * path. A new kind of light goes here ({@link rtd.scene.Light}). {@link rtd.scene.SceneWarnings} names
 * the slips that draw a picture without a word of why it looks wrong. Depends on the camera, geometry,
 * image and math packages.
 */
package rtd.scene;
