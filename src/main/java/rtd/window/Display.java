package rtd.window;

import java.util.List;
import rtd.image.Picture;

/** What the window shows, told by its session; called on the window's thread only. */
interface Display {

    /** The picture, or a view with its legend below it. */
    void picture(Picture picture);

    /** The selected pixel's ray tree, in image coordinates; empty for none. */
    void rays(List<RayTreeProjection.Line> lines);

    /** The side panel's text: the explanation, the copied camera, a scene's mistakes, the keys. */
    void panel(String text);

    void status(String text);

    /** The clock slider at {@code clock}, or hidden for null: the scene does not use {@code clock}. */
    void clock(Double clock);

    void copy(String text);
}
