package rtd.bench;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import javax.imageio.ImageIO;

/**
 * Draws bench/run.sh's results as a log-log chart: wall time against the number of spheres,
 * one line per renderer.
 *
 * <p>Usage: {@code java -cp bench/target/benchmarks.jar rtd.bench.ChartWriter results.csv chart.png}
 */
public final class ChartWriter {

    private static final int W = 900;
    private static final int H = 560;
    private static final int LEFT = 90;
    private static final int RIGHT = 230;
    private static final int TOP = 40;
    private static final int BOTTOM = 70;
    private static final Color[] COLOURS = {new Color(200, 60, 40), new Color(40, 110, 200), new Color(60, 150, 70),
        new Color(150, 80, 170)};

    private ChartWriter() {
    }

    public static void main(String[] args) throws IOException {
        Map<String, TreeMap<Double, Double>> series = new LinkedHashMap<>();
        List<String> lines = Files.readAllLines(Path.of(args[0]));
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",");
            series.computeIfAbsent(f[1], k -> new TreeMap<>()).put(Double.parseDouble(f[0]), Double.parseDouble(f[2]));
        }
        ImageIO.write(draw(series), "png", Path.of(args[1]).toFile());
    }

    private static BufferedImage draw(Map<String, TreeMap<Double, Double>> series) {
        double minN = 1;
        double maxN = 1e7;
        double minT = 0.1;
        double maxT = 100;
        BufferedImage image = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, W, H);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        for (double n = minN; n <= maxN; n *= 10) {
            int x = x(n, minN, maxN);
            g.setColor(new Color(225, 225, 225));
            g.drawLine(x, TOP, x, H - BOTTOM);
            g.setColor(Color.DARK_GRAY);
            g.drawString(String.format("%.0e", n).replace("e+0", "e"), x - 14, H - BOTTOM + 20);
        }
        for (double t = minT; t <= maxT; t *= 10) {
            int y = y(t, minT, maxT);
            g.setColor(new Color(225, 225, 225));
            g.drawLine(LEFT, y, W - RIGHT, y);
            g.setColor(Color.DARK_GRAY);
            g.drawString(t < 1 ? String.valueOf(t) : String.format("%.0f", t), LEFT - 40, y + 5);
        }
        g.drawString("spheres (log)", (LEFT + W - RIGHT) / 2 - 40, H - 25);
        g.drawString("wall time in seconds, 1920×1080, whole process (log)", LEFT, TOP - 15);
        int i = 0;
        for (Map.Entry<String, TreeMap<Double, Double>> entry : series.entrySet()) {
            g.setColor(COLOURS[i % COLOURS.length]);
            g.setStroke(new BasicStroke(2.5f));
            int[] previous = null;
            for (Map.Entry<Double, Double> point : entry.getValue().entrySet()) {
                int[] p = {x(point.getKey(), minN, maxN), y(point.getValue(), minT, maxT)};
                g.fillOval(p[0] - 4, p[1] - 4, 8, 8);
                if (previous != null) {
                    g.drawLine(previous[0], previous[1], p[0], p[1]);
                }
                previous = p;
            }
            g.drawString(entry.getKey(), W - RIGHT + 20, TOP + 30 + 25 * i);
            i++;
        }
        g.dispose();
        return image;
    }

    private static int x(double n, double min, double max) {
        return LEFT + (int) Math.round((W - LEFT - RIGHT) * Math.log(n / min) / Math.log(max / min));
    }

    private static int y(double t, double min, double max) {
        double clamped = Math.max(min, Math.min(max, t));
        return H - BOTTOM - (int) Math.round((H - TOP - BOTTOM) * Math.log(clamped / min) / Math.log(max / min));
    }
}
