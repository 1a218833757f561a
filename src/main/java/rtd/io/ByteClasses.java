package rtd.io;

/** Which bytes of a scene file are blanks, letters of a keyword, or end a number. */
final class ByteClasses {

    private ByteClasses() {
    }

    static boolean isBlank(byte b) {
        return b == ' ' || b == '\t' || b == '\r' || b == '\f' || b == 0x0B;
    }

    static boolean isWordByte(byte b) {
        return (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || b == '_';
    }

    static boolean isDelimiter(byte b) {
        return b == '|' || b == ')' || b == '(' || b == ':' || b == '\n' || isBlank(b);
    }
}
