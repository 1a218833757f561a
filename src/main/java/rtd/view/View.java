package rtd.view;

/**
 * What a debug view shows of each pixel's ray ({@code --view}): what the ray did rather than
 * what it saw. Not in the paper; it makes the cost of its loop (Listing 4.3) and the depth test
 * (section 3.2.3) visible.
 */
public enum View {
    /** The intersection tests the ray took, as a heat map on a logarithmic scale. */
    cost,
    /** The depth test's distance {@code |P − O|} in grey, near bright. */
    depth,
    /** The unit normal N at the hit point as colour, {@code (N + 1)/2} a channel. */
    normal,
    /** One colour per object. */
    id
}
