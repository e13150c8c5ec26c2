package org.proactiverobotics.app;

import java.util.Locale;

/** A count with its noun, singular for exactly one: "1 recharge", "0 recharges", "3 recharges". */
public final class Plural {

    private Plural() {
    }

    /**
     * @param count    how many
     * @param singular the noun for one; its plural adds "s"
     * @return e.g. {@code 1 recharge}, {@code 2 recharges}
     */
    public static String of(long count, String singular) {
        return String.format(Locale.ROOT, "%d %s", count, count == 1 ? singular : singular + "s");
    }
}
