/**
 * {@code --view KIND}: pictures of what the rays did rather than what they saw: the tests per ray
 * (the paper's cost, N tests a ray, against the faster paths), the depth, the normals, the objects.
 * A teaching tool, not in the paper.
 */
package rtd.view;
