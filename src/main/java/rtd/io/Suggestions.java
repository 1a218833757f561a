package rtd.io;

import java.util.Collection;
import java.util.Locale;

/** Finds the word a misspelt one was probably meant to be ("did you mean 'sphere'?"). */
final class Suggestions {

    private Suggestions() {
    }

    /** The statement keyword nearest to {@code word}, or null if none is near enough. */
    static String nearestKeyword(String word) {
        return nearest(word, Grammar.STATEMENTS.stream().map(Statement::keyword).toList());
    }

    /**
     * The candidate nearest to {@code word} (the first in alphabetical order of equally near
     * ones), or null if none is near enough: within two edits, or a third of the candidate's
     * length for long words. Case is ignored, so that {@code IOR} finds {@code ior}.
     */
    static String nearest(String word, Collection<String> candidates) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String candidate : candidates.stream().sorted().toList()) {
            int distance = editDistance(word.toLowerCase(Locale.ROOT), candidate.toLowerCase(Locale.ROOT));
            if (distance < bestDistance) {
                bestDistance = distance;
                best = candidate;
            }
        }
        return best != null && bestDistance <= Math.max(2, best.length() / 3) ? best : null;
    }

    /** The Levenshtein distance: the fewest single-character edits that turn a into b. */
    static int editDistance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitution = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitution, Math.min(previous[j], current[j - 1]) + 1);
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[b.length()];
    }
}
