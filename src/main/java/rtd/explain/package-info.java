/**
 * {@code --explain X,Y}: the paper's steps for one pixel with the renderer's own numbers, which the tests and the
 * shader report to observers ({@code rtd.geometry.TestObserver}, {@code rtd.shade.ShadingObserver}) as they run:
 * nothing is computed a second time. A teaching tool, not in the paper.
 */
package rtd.explain;
