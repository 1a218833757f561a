/**
 * {@code --explain X,Y}: the paper's steps for one pixel, with the renderer's own numbers (the ray of Listing 4.1, each
 * object's test, for a sphere by equations 3.6 to 3.8, the depth test of Listing 4.3, the colour, and with lights the
 * shading tree). Nothing is computed a second time: the tests and the shader report their numbers to observers
 * ({@code rtd.geometry.TestObserver}, {@code rtd.shade.ShadingObserver}) as they run. A teaching tool, not in the
 * paper.
 */
package rtd.explain;
