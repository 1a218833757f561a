package rtd.io;

import java.util.Arrays;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.ToIntFunction;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.IntStream;

/**
 * The {@code = help:} lines for the mistakes people really make in a scene file (a decimal comma, an invisible
 * character, the paper's line numbers…), and "did you mean …?" for a misspelt word or a synonym ({@code kugel}).
 */
public final class Hints {

    static final String COMMENTS = "comments start with //";
    /** The forms of a number; "or" between them, since a comma would read as a decimal comma. */
    static final String NUMBER_FORMS = "numbers are written like 3 or -0.5 or .5 or 1. or 2e3";
    static final String LINE_NUMBERS = "it looks like the lines are numbered, as in the paper's listing: "
            + "remove the numbers at the start of each line";
    static final String FLOAT_RANGE = "a float holds numbers up to about 3.4e38";
    static final String SEMICOLON = "one statement per line, with nothing after it: remove the ';'";

    /** One number, with a comma where the point should be: 2,5 or -0,5 or 1,5e3. */
    private static final Pattern DECIMAL_COMMA = Pattern.compile("[+-]?[0-9]*,[0-9]+([eE][+-]?[0-9]+)?");
    /** A token that begins as {@code (at x|y|z)} does, misspelt: {@code at0}, {@code AT}, {@code At-1}. */
    private static final Pattern LOOK_AT = Pattern.compile("(?i)at[-+.0-9]*");

    /**
     * Words people write for a statement (English, German, other tools' words) by the keywords they suggest; looked
     * up before the spelling, as "bg" is two edits from "box" but means the background.
     */
    static final Map<String, List<String>> SYNONYMS = """
            camera cam kamera view eye = orthographic_camera perspective_camera
            ortho orthographic orthocamera = orthographic_camera
            perspective persp perspectivecamera = perspective_camera
            ball kugel circle kreis globe = sphere
            background hintergrund bg color colour farbe backgroundcolor sky = ambient
            lamp licht lichtquelle pointlight point_light lightsource light_source sun = light
            floor ground boden ebene wall = plane
            cube cuboid quader wuerfel aabb = box
            tri dreieck face = triangle
            obj model modell = mesh
            mat finish surface = material
            texture textur pigment muster checkerboard checkers stripe ring = pattern
            matrix transformation scale rotate translate move = transform
            cyl zylinder tube pipe rod = cylinder
            kegel = cone
            arealight area softlight soft_light flaechenlicht = area_light
            """.lines().map(line -> line.split(" = "))
            .flatMap(row -> Arrays.stream(row[0].split(" ")).map(word -> Map.entry(word, List.of(row[1].split(" ")))))
            .collect(Collectors.toUnmodifiableMap(Map.Entry::getKey, Map.Entry::getValue));

    private Hints() {
    }

    /** For a token that is no number; {@code wholeNumberGroup} names its group if that takes whole numbers only. */
    static String forNumber(String token, String wholeNumberGroup) {
        if (token.indexOf('\u2212') >= 0) {
            return "'\u2212' is a typographic minus sign (U+2212); type the plain '-' instead";
        }
        if (DECIMAL_COMMA.matcher(token).matches()) {
            return wholeNumberGroup == null ? "write decimals with a point: " + token.replace(',', '.')
                    : "in " + wholeNumberGroup + ", write whole numbers separated by '|', not ','";
        }
        if (token.indexOf(',') >= 0) {
            return "separate the numbers of a group with '|', not ','";
        }
        if (token.indexOf(';') >= 0) {
            return "separate the numbers of a group, or its properties, with '|', not ';'";
        }
        return LOOK_AT.matcher(token).matches()
                ? "a camera looks at a point when its direction is written (at x|y|z): 'at' in lower case, then a space"
                : NUMBER_FORMS;
    }

    static String forWindowsPath(String path) {
        return "write folders with '/', as in " + path.replace('\\', '/') + ", which works on every system; "
                + "'\\' separates folders on Windows only";
    }

    /** For an OBJ token that is no number: blanks separate its numbers, so a comma is a decimal comma. */
    static String forObjNumber(String token) {
        return DECIMAL_COMMA.matcher(token).matches() ? "write decimals with a point: " + token.replace(',', '.')
                : NUMBER_FORMS;
    }

    /** Whether a character shows as a blank or not at all, but is no space or tab: U+00A0, U+200B, U+FEFF… */
    static boolean isInvisible(int codePoint) {
        return codePoint > 0x7F
                && (Character.isSpaceChar(codePoint) || Character.getType(codePoint) == Character.FORMAT);
    }

    /** "U+00A0 NO-BREAK SPACE": how a message names an invisible character. */
    static String nameOf(int codePoint) {
        String name = Character.getName(codePoint);
        String text = String.format("U+%04X", codePoint) + (name == null ? "" : " " + name);
        return codePoint == 0xFEFF ? text + " (a byte-order mark)" : text;
    }

    static String forInvisible(int codePoint) {
        if (codePoint == 0xFEFF) {
            return "a byte-order mark may stand only at the very start of a file (one gets inside when files are "
                    + "joined): delete it";
        }
        boolean looksLikeSpace = Character.isSpaceChar(codePoint)
                && !Character.getName(codePoint).contains("ZERO WIDTH");
        return String.format("U+%04X", codePoint) + (looksLikeSpace
                ? " looks like a space but is not one: type a plain space instead"
                : " cannot be seen but is there: delete it") + " (text copied from a PDF or a web page brings it)";
    }

    /** The help for a name in {@code group} from {@code start}, then something else: properties get their own. */
    static String forName(LineCursor cursor, Group group, int start) {
        if (!cursor.at('=')) {
            return "a name holds only letters, digits, '_' and '-'";
        }
        int end = start;
        while (end < cursor.bytes.length && cursor.bytes[end] != ')' && !TextBytes.isLineBreak(cursor.bytes[end])) {
            end++;
        }
        String properties = cursor.source.text(start, end).strip();
        return group == Statement.MATERIAL
                ? "an object names its material here; define the material on a line of its own, such as "
                        + "material:(shiny):(" + properties + "), then write (shiny) here"
                : "a material's name comes first, then its properties: material:(shiny):(" + properties + ")";
    }

    /** For a colour written as fractions from 0 to 1, as other programs write it, the same from 0 to 255; else null. */
    static String colourFractions(float[] values) {
        if (!IntStream.range(0, 3).allMatch(i -> values[i] >= 0 && values[i] <= 1)) {
            return null;
        }
        return "rtd's colours run from 0 to 255, not from 0 to 1: this colour is (" + IntStream.range(0, 3)
                .mapToObj(i -> String.valueOf(Math.round(values[i] * 255))).collect(Collectors.joining("|")) + ")";
    }

    static String keywordHelp(String word) {
        List<String> meant = SYNONYMS.get(word.toLowerCase(Locale.ROOT));
        if (meant != null) {
            return "did you mean '" + String.join("' or '", meant) + "'?";
        }
        return didYouMean(nearest(word, Grammar.STATEMENTS.stream().map(Statement::keyword).toList()),
                "a statement starts with " + Grammar.keywordList());
    }

    /** Whether a number that read as no finite float was written too large for one, not as NaN or Infinity. */
    static boolean tooLarge(String written) {
        return !written.contains("NaN") && !written.contains("Infinity");
    }

    /** The words a message lists, quoted: "'a', 'b' and 'c'" for {@code last} = "and". */
    static String quoted(List<String> words, String last) {
        List<String> each = words.stream().map(word -> "'" + word + "'").toList();
        return String.join(", ", each.subList(0, each.size() - 1)) + " " + last + " " + each.get(each.size() - 1);
    }

    /** "did you mean …?" with the one of {@code words} nearest to {@code word}, else their list: "the keys are …". */
    static String nearestOrList(String word, List<String> words, String plural) {
        return didYouMean(nearest(word, words), "the " + plural + " are " + quoted(words, "and"));
    }

    /** "did you mean 'nearest'?", or {@code otherwise} if {@code nearest} is null. */
    static String didYouMean(String nearest, String otherwise) {
        return nearest != null ? "did you mean '" + nearest + "'?" : otherwise;
    }

    /**
     * The candidate nearest to {@code word}, case ignored (the first in alphabetical order of equally near ones), or
     * null if none is within two edits, or a third of the candidate's length for long words.
     */
    public static String nearest(String word, Collection<String> candidates) {
        ToIntFunction<String> distance = candidate -> editDistance(word.toLowerCase(Locale.ROOT),
                candidate.toLowerCase(Locale.ROOT));
        return candidates.stream().sorted().min(Comparator.comparingInt(distance)) // min keeps the first of equals
                .filter(best -> distance.applyAsInt(best) <= Math.max(2, best.length() / 3)).orElse(null);
    }

    /** The Levenshtein distance: the fewest single-character edits that turn a into b. */
    static int editDistance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        Arrays.setAll(previous, j -> j);
        for (int i = 1; i <= a.length(); i++) {
            int[] current = new int[b.length() + 1];
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitution = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitution, Math.min(previous[j], current[j - 1]) + 1);
            }
            previous = current;
        }
        return previous[b.length()];
    }
}
