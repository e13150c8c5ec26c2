package org.proactiverobotics.app.sweep;

import java.util.function.Function;

/** What the summary groups a sweep's missions by: a column of the strategy × noise × world kind tables. */
public enum Factor {
    /** The strategy the engine started with. */
    STRATEGY("strategy", SummaryHtml.Row::strategy),
    /** The sensors' noise level. */
    NOISE("noise", SummaryHtml.Row::noise),
    /** The kind of a world {@code generate} drew; "—" for a world named by hand (see {@link SummaryHtml.Row#kind()}). */
    KIND("world kind", r -> r.kind().orElse(SuccessRate.NONE));

    private final String label;
    private final Function<SummaryHtml.Row, String> value;

    Factor(String label, Function<SummaryHtml.Row, String> value) {
        this.label = label;
        this.value = value;
    }

    /** @return its name as a column heading */
    public String label() {
        return label;
    }

    /**
     * @param row a mission
     * @return the mission's value of this factor
     */
    public String of(SummaryHtml.Row row) {
        return value.apply(row);
    }
}
