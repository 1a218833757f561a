/**
 * Colours and pictures: the paper's 8-bit {@link rtd.image.Color} (section 4.1), the float
 * colour {@link rtd.image.Rgb} that shading adds up (Part II, "Light"), and {@link rtd.image.Picture},
 * the rendered pixels (the picture that Listing 4.2 fills). Depends on nothing else of rtd.
 */
package rtd.image;
