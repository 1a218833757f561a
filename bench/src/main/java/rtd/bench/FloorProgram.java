package rtd.bench;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.util.Arrays;
import java.util.concurrent.Callable;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * The floor for the paper's example: the least a program on rtd's stack (Java 17, picocli,
 * {@code javax.imageio}) must do to turn a scene file into a 1920 × 1080 PNG. It reads the file,
 * and writes one flat colour through the same PNG writer and deflate level as rtd, so that
 * {@code bench/targets.sh} can say how much of rtd's time for the paper's example is its own.
 * Built into {@code bench/target/floor.jar} with nothing but picocli beside it.
 */
@Command(name = "floor", mixinStandardHelpOptions = true, description = "Writes a flat PNG (a benchmark floor).")
public final class FloorProgram implements Callable<Integer> {

    @Parameters(paramLabel = "SCENE", description = "The scene file (read, not interpreted).")
    private File scene;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE", required = true, description = "The PNG to write.")
    private File output;

    @Option(names = "--width", defaultValue = "1920", description = "Width in pixels.")
    private int width;

    @Option(names = "--height", defaultValue = "1080", description = "Height in pixels.")
    private int height;

    public static void main(String[] args) {
        System.exit(new CommandLine(new FloorProgram()).execute(args));
    }

    @Override
    public Integer call() throws IOException {
        byte[] text = Files.readAllBytes(scene.toPath());
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        int[] pixels = new int[width * height];
        Arrays.fill(pixels, 0x7FFFFF ^ (text.length & 1)); // the paper's sky, (127|255|255)
        image.setRGB(0, 0, width, height, pixels, 0, width);
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        ImageWriteParam parameters = writer.getDefaultWriteParam();
        parameters.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
        parameters.setCompressionQuality(0.9f); // rtd's level
        try (ImageOutputStream stream = ImageIO.createImageOutputStream(output)) {
            writer.setOutput(stream);
            writer.write(null, new IIOImage(image, null, null), parameters);
        } finally {
            writer.dispose();
        }
        return 0;
    }
}
