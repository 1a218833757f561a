package rtd.io;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;

/**
 * Where {@link SceneParser} cuts a scene file into parts that {@link StatementReader}s read in
 * parallel: just after line breaks, about a part's size apart; and, before any part is read, each
 * part's {@link TextScan} (whether it is text, and its line breaks), from which each part's
 * first line number follows.
 */
final class FileCuts {

    private FileCuts() {
    }

    /**
     * Whether the file is small enough to be one part. It is then read on the calling thread
     * alone, with no parallel stream: starting one would take longer than reading the file.
     */
    static boolean onePart(int[] cuts) {
        return cuts.length == 2;
    }

    /**
     * Where the parts start, each just after a line break (never between the CR and the LF of
     * one), and the end of the file last.
     */
    static int[] cuts(byte[] bytes, int start, int partSize) {
        int count = Math.max(1, (bytes.length - start) / partSize);
        List<Integer> cuts = new ArrayList<>();
        cuts.add(start);
        for (int k = 1; k < count; k++) {
            int cut = start + (int) ((long) (bytes.length - start) * k / count);
            while (cut < bytes.length && !ByteClasses.endsLine(bytes, cut - 1)) {
                cut++;
            }
            if (cut > cuts.get(cuts.size() - 1) && cut < bytes.length) {
                cuts.add(cut);
            }
        }
        cuts.add(bytes.length);
        int[] array = new int[cuts.size()];
        for (int k = 0; k < array.length; k++) {
            array[k] = cuts.get(k);
        }
        return array;
    }

    /**
     * Each part's {@link TextScan}, in parallel if there are several. Only a part that is text
     * is read, so its first line number is known before it is.
     */
    static TextScan[] scan(byte[] bytes, int[] cuts) {
        if (onePart(cuts)) {
            return new TextScan[] {TextScan.of(bytes, cuts[0], cuts[1])};
        }
        return IntStream.range(0, cuts.length - 1).parallel()
                .mapToObj(k -> TextScan.of(bytes, cuts[k], cuts[k + 1]))
                .toArray(TextScan[]::new);
    }

    /** The number of the first line of each part, and last the number a line after the last part would have. */
    static int[] firstLines(TextScan[] scans) {
        int[] firstLines = new int[scans.length + 1];
        firstLines[0] = 1;
        for (int k = 1; k <= scans.length; k++) {
            firstLines[k] = firstLines[k - 1] + scans[k - 1].lineBreaks();
        }
        return firstLines;
    }
}
