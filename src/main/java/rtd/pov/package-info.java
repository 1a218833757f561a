/**
 * {@code --export-pov}: the scene written for POV-Ray 3.7, so that another ray tracer can draw the same picture as a
 * second opinion (Part II, "POV-Ray"). A teaching tool, not in the paper.
 */
package rtd.pov;
