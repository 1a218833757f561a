/**
 * Colour above the hit: the paper's flat colours ({@link rtd.shade.FlatShader}, section 3.2.3) and
 * Whitted ray tracing with lights, shadows, reflection and refraction
 * ({@link rtd.shade.WhittedShader}, Part II, "Light", steps 1 to 6: the chapter the paper names as
 * the way on, sections 3.2.3 and 5). Implements {@code rtd.render.Shader}.
 */
package rtd.shade;
