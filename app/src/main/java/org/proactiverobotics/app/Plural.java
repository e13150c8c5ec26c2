package org.proactiverobotics.app;

import java.util.Locale;

/** A count with its noun, singular for exactly one: "1 recharge", "0 recharges", "1 strategy", "3 strategies". */
public final class Plural {

    private Plural() {
    }

    /**
     * @param count    how many
     * @param singular the noun for one; its plural adds "s"
     * @return e.g. {@code 1 recharge}, {@code 2 recharges}
     */
    public static String of(long count, String singular) {
        return of(count, singular, singular + "s");
    }

    /**
     * @param count    how many
     * @param singular the noun for one
     * @param plural   the noun for any other count ({@code strategies})
     * @return e.g. {@code 1 strategy}, {@code 2 strategies}
     */
    public static String of(long count, String singular, String plural) {
        return String.format(Locale.ROOT, "%d %s", count, count == 1 ? singular : plural);
    }
}
