/**
 * Cameras, which make the ray through each pixel (section 3.2.1, ray generation):
 * {@link rtd.camera.OrthographicCamera} (Listing 4.1) and {@link rtd.camera.PerspectiveCamera}
 * (Part II, "The perspective camera"), both behind {@link rtd.camera.ICamera}. A new camera goes
 * here. Depends on {@code rtd.math} only.
 */
package rtd.camera;
