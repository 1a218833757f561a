package rtd.window;

/** The window's keys and mouse, as its panel shows them before a pixel is selected (and the README's table). */
final class Keys {

    static final String HELP = String.join("\n",
            "rtd's window: click a pixel to see what rtd does for it.",
            "",
            "  drag        orbit around what the centre pixel sees",
            "  right drag  pan (or Shift + drag)",
            "  wheel       zoom",
            "  click       explain the pixel, its rays over the picture",
            "  1 to 5      picture, cost, depth, normal, id (V: next)",
            "  R           the file's camera again",
            "  C           copy the camera as a scene line",
            "  P           play the clock, 0 to 1 in 5 s, or pause",
            "  Ctrl+S      save the picture as NAME-window.png",
            "  Esc         no pixel selected",
            "  Q           quit",
            "",
            "Saving the scene file renders it again. A scene that uses clock",
            "has a clock slider above this panel.",
            "");

    private Keys() {
    }
}
