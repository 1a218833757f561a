/**
 * {@code --explain X,Y}: the paper's steps for one pixel, with the renderer's own numbers (the ray
 * of Listing 4.1, each object's test by equations 3.6 to 3.8, the depth test of Listing 4.3, the
 * colour, and with lights the shading tree). A teaching tool, not in the paper.
 */
package rtd.explain;
