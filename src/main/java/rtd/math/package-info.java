/**
 * Vectors and rays in single precision, as the paper computes them: {@link rtd.math.Vector3f}
 * (section 4.2.1, Listing B.1) and {@link rtd.math.Ray} (section 3.2.1, equation 3.1). The lowest
 * layer: it depends on nothing else of rtd.
 */
package rtd.math;
