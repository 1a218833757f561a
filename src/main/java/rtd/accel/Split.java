package rtd.accel;

/**
 * Where a node's objects divide (place {@code middle} is the right child's first) and end
 * (before any twins left out), the children's extents, if known, and the arrays that hold
 * the children's objects: the answer of {@link SahSplitter}, by which the {@link BvhBuilder}
 * makes a node's children.
 *
 * @param middle the right child's first place
 * @param end the end of the node's places in the tree, before any twins left out
 * @param left the left child's extent, or {@code null} if the builder is to measure it
 * @param right the right child's extent, or {@code null} if the builder is to measure it
 * @param data the arrays that hold the children's objects
 */
record Split(int middle, int end, Extent left, Extent right, ObjectArrays data) {
}
