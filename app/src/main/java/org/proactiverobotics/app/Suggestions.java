package org.proactiverobotics.app;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * What a mistyped option or command most likely meant: the names a letter or two away from it
 * ({@code --wrld} → {@code --world}), closest first. Picocli's own guess only compares the first
 * two letters of an option and the letter pairs of a command, and misses most typos.
 */
final class Suggestions {

    /** At most this many edits (a letter left out, added, changed, or two swapped) from the name typed. */
    private static final int MAX_EDITS = 2;
    /** Names shorter than this ({@code -h}) are never guessed at, nor guessed: any letter is one edit from another. */
    private static final int MIN_LETTERS = 2;

    private Suggestions() {
    }

    /**
     * @param typed what was typed ({@code --wrld}, {@code --wrld=x}, {@code swep})
     * @param names the names there are
     * @return the names of two letters or more at most two edits away (one for a word of up to five
     *         letters), closest first
     */
    static List<String> closest(String typed, Collection<String> names) {
        String word = bare(typed);
        if (word.length() < MIN_LETTERS) {
            return List.of();
        }
        int most = Math.min(MAX_EDITS, Math.max(1, word.length() / 3));
        List<String> near = new ArrayList<>();
        for (String name : names) {
            if (bare(name).length() >= MIN_LETTERS && edits(word, bare(name)) <= most && !near.contains(name)) {
                near.add(name);
            }
        }
        near.sort(Comparator.comparingInt(name -> edits(word, bare(name))));
        return near;
    }

    /** The name without its dashes or a value given with '=', in lower case. */
    private static String bare(String s) {
        int eq = s.indexOf('=');
        return (eq < 0 ? s : s.substring(0, eq)).replaceFirst("^-+", "").toLowerCase(Locale.ROOT);
    }

    /** Optimal string alignment distance: insertions, deletions, substitutions and swaps of neighbours. */
    static int edits(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }
}
