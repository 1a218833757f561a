package rtd.io;

import java.awt.image.BufferedImage;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Map;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import rtd.image.Picture;

/**
 * An animated GIF that loops for ever (Part III, "Frames on the command line"), written frame by frame, each
 * waiting its delay; the first carries the NETSCAPE2.0 extension that makes players loop. Each frame gets its own
 * palette, without dithering: less banding and a smaller file than one palette for all. The file replaces the
 * output only in {@link #finish}, all or nothing ({@link TemporaryFiles}).
 */
public final class AnimatedGif implements AutoCloseable {

    private static final String FORMAT = "javax_imageio_gif_image_1.0";

    private final OutputStream out;
    private final int delay;
    /** The temporary file that replaces the output, or null when written into a device as it is. */
    private final TemporaryFiles.Replacement temporary;
    private final ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
    private final ImageOutputStream stream;
    private boolean started;
    private boolean finished;

    private AnimatedGif(OutputStream out, int delay, TemporaryFiles.Replacement temporary) throws IOException {
        this.out = new BufferedOutputStream(out, 1 << 16);
        this.delay = delay;
        this.temporary = temporary;
        this.stream = new MemoryCacheImageOutputStream(this.out);
        writer.setOutput(stream);
        writer.prepareWriteSequence(null);
    }

    /** A GIF that replaces the regular file {@code output} once finished; {@code delay} in hundredths of a second. */
    public static AnimatedGif replacing(Path output, int delay) throws IOException {
        TemporaryFiles.Replacement temporary = TemporaryFiles.create(output);
        try {
            return new AnimatedGif(temporary.out(), delay, temporary);
        } catch (IOException | RuntimeException e) {
            temporary.discard();
            throw e;
        }
    }

    /** A GIF written into {@code device} (a FIFO, /dev/null) as it is made. */
    public static AnimatedGif into(Path device, int delay) throws IOException {
        return new AnimatedGif(Files.newOutputStream(device, StandardOpenOption.WRITE), delay, null);
    }

    public void add(Picture picture) throws IOException {
        BufferedImage image = ImageFormat.asImage(picture);
        ImageWriteParam param = writer.getDefaultWriteParam();
        IIOMetadata metadata = writer.getDefaultImageMetadata(new ImageTypeSpecifier(image), param);
        IIOMetadataNode root = (IIOMetadataNode) metadata.getAsTree(FORMAT);
        IIOMetadataNode control = child(root, "GraphicControlExtension");
        Map.of("disposalMethod", "none", "userInputFlag", "FALSE", "transparentColorFlag", "FALSE", "delayTime",
                Integer.toString(delay), "transparentColorIndex", "0").forEach(control::setAttribute);
        if (!started) {
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0}); // sub-block 1: loop count 0, for ever
            child(root, "ApplicationExtensions").appendChild(loop);
        }
        metadata.setFromTree(FORMAT, root);
        writer.writeToSequence(new IIOImage(image, null, metadata), param);
        started = true;
    }

    public void finish() throws IOException {
        writer.endWriteSequence();
        stream.flush();
        out.close();
        if (temporary != null) {
            temporary.commit();
        }
        finished = true;
    }

    /** Lets the writer go; an unfinished GIF's temporary file is deleted. */
    @Override
    public void close() throws IOException {
        writer.dispose();
        if (!finished) {
            out.close();
            if (temporary != null) {
                temporary.discard();
            }
        }
    }

    /** The child of {@code root} named {@code name}, added if it has none. */
    private static IIOMetadataNode child(IIOMetadataNode root, String name) {
        if (root.getElementsByTagName(name).getLength() > 0) {
            return (IIOMetadataNode) root.getElementsByTagName(name).item(0);
        }
        return (IIOMetadataNode) root.appendChild(new IIOMetadataNode(name));
    }
}
