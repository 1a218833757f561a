package rtd.io;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.function.IntFunction;
import java.util.stream.IntStream;

/**
 * A scene file cut just after line breaks into parts of about {@link #PART_SIZE} bytes, each with the number of
 * its first line, so that the parts after the first are read in parallel, each by its own reader. The first part is
 * read first, on the calling thread; then each other part is joined in file order if it stands alone: no mistake,
 * no line number, no definition, no {@code let} and no clock in it. Read from the first part that does not, the
 * rest is read again in order by the first part's reader, so the scene, its mistakes and its warnings are those of
 * reading the whole file in order, whatever the number of threads. The parallel work runs on a pool of its own, of
 * at most the threads asked; with one thread the file is one part, read in order on the calling thread.
 */
final class FileParts {

    /** The size of a part: large enough to be worth a thread, small enough for two threads to share evenly. */
    static final int PART_SIZE = 4 << 20;
    /** Fewer bytes than any line that makes an object, {@code sphere:(0|0|0):(1):(0|0|0)} and its line break. */
    private static final int SHORTEST_OBJECT = 24;

    private final SourceText source;
    private final int threads;
    /** Each part's first byte, and the end of the file last. */
    private final int[] cuts;
    /** Each part's first line, and last the number a line after the file would have. */
    private final int[] lines;

    /** A part read on its own, and whether it can be joined to the parts above it as it is. */
    private record Part(SceneContents contents, boolean standsAlone) {
    }

    private FileParts(SourceText source, int threads, int[] cuts, int[] lines) {
        this.source = source;
        this.threads = threads;
        this.cuts = cuts;
        this.lines = lines;
    }

    /**
     * The text of {@code source} from {@code start} in parts of about {@code partSize} bytes, to be read with at most
     * {@code threads} threads; it must be UTF-8.
     */
    static FileParts of(SourceText source, int start, int partSize, int threads) throws SceneException {
        byte[] bytes = source.bytes();
        int count = threads == 1 ? 1 : Math.max(1, (bytes.length - start) / partSize);
        int[] cuts = new int[count + 1];
        int parts = 0;
        cuts[0] = start;
        for (int k = 1; k < count; k++) {
            int cut = start + (int) ((long) (bytes.length - start) * k / count);
            while (cut < bytes.length && !TextBytes.endsLine(bytes, cut - 1)) {
                cut++; // never between the CR and the LF of one line break
            }
            if (cut > cuts[parts] && cut < bytes.length) {
                cuts[++parts] = cut;
            }
        }
        cuts[++parts] = bytes.length;
        cuts = Arrays.copyOf(cuts, parts + 1);
        return new FileParts(source, threads, cuts, linesAtCuts(source, cuts, threads));
    }

    /**
     * The number of the line at each cut, from one pass over each part's bytes (the parts in parallel) that also
     * refuses text that is not UTF-8.
     */
    private static int[] linesAtCuts(SourceText source, int[] cuts, int threads) throws SceneException {
        byte[] bytes = source.bytes();
        int[] breaks = inParallel(cuts.length - 1, threads, k -> lineBreaks(bytes, cuts[k], cuts[k + 1])).stream()
                .mapToInt(Integer::intValue).toArray();
        int[] lines = new int[cuts.length];
        lines[0] = 1;
        boolean plain = true;
        for (int k = 0; k < breaks.length; k++) {
            plain &= breaks[k] >= 0;
            lines[k + 1] = lines[k] + (breaks[k] & Integer.MAX_VALUE);
        }
        int bad = plain ? -1 : SourceText.firstBadByte(bytes, cuts[0], bytes.length);
        if (bad >= 0) {
            throw new SceneException(List.of(source.notUtf8(cuts[0], bad)), false);
        }
        return lines;
    }

    /** The line breaks in {@code bytes[from, to)}; the sign bit set if a byte there may not be UTF-8's ASCII. */
    private static int lineBreaks(byte[] bytes, int from, int to) {
        int breaks = 0;
        boolean plain = true;
        for (int i = from; i < to; i++) {
            if (bytes[i] <= '\r') { // one test for the rare: line breaks, control characters, every non-ASCII byte
                breaks += bytes[i] == '\n' || bytes[i] == '\r' && TextBytes.endsLine(bytes, i) ? 1 : 0;
                plain &= bytes[i] > 0;
            }
        }
        return plain ? breaks : breaks | Integer.MIN_VALUE;
    }

    /**
     * How many objects parts {@code from} to {@code to} (exclusive) make at most, so that their list is made that
     * long at once: grown line by line, its large arrays would go to the old generation, and stay there long.
     */
    int objectsAtMost(int from, int to) {
        return Math.min(lines[to] - lines[from] + 1, (cuts[to] - cuts[from]) / SHORTEST_OBJECT + 1);
    }

    int count() {
        return cuts.length - 1;
    }

    /**
     * Reads every part into {@code contents} with {@code reader}, which starts at the first part, the others in
     * parallel where they stand alone; answers how many parts were read on their own and joined.
     */
    int read(StatementReader reader, SceneContents contents, Names names) {
        try {
            reader.readUntil(cuts[1]);
            int next = 1;
            if (count() > 1 && contents.errors.isEmpty()) {
                List<Part> parts = inParallel(count() - 1, threads, k -> readAlone(k + 1, contents, names));
                while (next < count() && parts.get(next - 1).standsAlone()) {
                    contents.append(parts.get(next++ - 1).contents());
                }
            }
            if (next < count()) {
                reader.moveTo(cuts[next], lines[next]);
                reader.readUntil(cuts[count()]);
            }
            return next - 1;
        } finally {
            reader.release();
        }
    }

    /**
     * What {@code task} gives for each of {@code 0} to {@code count - 1}, in that order, worked out on a pool of at
     * most {@code threads} threads (a parallel stream runs on the pool its caller runs on); one task: on this thread.
     */
    private static <T> List<T> inParallel(int count, int threads, IntFunction<T> task) {
        if (count == 1) {
            return List.of(task.apply(0));
        }
        ForkJoinPool pool = new ForkJoinPool(Math.min(count, threads));
        try {
            return pool.submit(() -> IntStream.range(0, count).parallel().mapToObj(task).toList()).join();
        } finally {
            pool.shutdown();
        }
    }

    /** Part {@code k} read on its own, knowing the materials and the names that the first part defines. */
    private Part readAlone(int k, SceneContents first, Names names) {
        SceneContents contents = new SceneContents(objectsAtMost(k, k + 1));
        contents.materials.putAll(first.materials);
        Names own = names.forPart();
        StatementReader reader = new StatementReader(source, cuts[k], lines[k], contents, own);
        try {
            reader.readUntil(cuts[k + 1]);
        } catch (RuntimeException e) { // read again in order, where it fails the same way on every run
            return new Part(contents, false);
        } finally {
            reader.release();
        }
        return new Part(contents, contents.errors.isEmpty() && contents.lineNumbers == 0
                && contents.definitions.isEmpty() && own.definesNothingBeyond(names));
    }
}
