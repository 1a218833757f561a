package rtd.io;

/**
 * What one pass over a part of a scene file tells before the part is read: whether it is text
 * (the offset of its first byte that is not, as {@link NotText} finds it), and how many lines
 * end in it, from which the next part's first line number follows.
 *
 * <p>Both come from the same pass because it is the only one that must read every byte before
 * the parts are read: a second would cost as much again, and early in a run, before the JIT has
 * compiled it, that is a good part of the time to read a large file.
 *
 * @param badByte    the offset of the first NUL byte or invalid UTF-8 sequence, or −1 if none
 * @param lineBreaks the number of line breaks (LF, CR LF or a CR alone); only counted if it is text
 */
record TextScan(int badByte, int lineBreaks) {

    /** Scans {@code bytes[from, to)}, which starts a line and ends after a line break or at the end of the file. */
    static TextScan of(byte[] bytes, int from, int to) {
        int lineBreaks = 0;
        boolean ascii = true;
        for (int i = from; i < to; i++) {
            byte b = bytes[i];
            if (b <= '\r') { // one test for the rare bytes: line breaks, control characters, and every non-ASCII byte
                if (b == '\n' || b == '\r' && ByteClasses.endsLine(bytes, i)) {
                    lineBreaks++;
                } else if (b == 0) {
                    return new TextScan(NotText.firstBadByte(bytes, from, to), lineBreaks);
                } else if (b < 0) {
                    ascii = false;
                }
            }
        }
        return new TextScan(ascii ? -1 : NotText.firstBadByte(bytes, from, to), lineBreaks);
    }
}
