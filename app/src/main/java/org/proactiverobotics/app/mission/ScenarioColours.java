package org.proactiverobotics.app.mission;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The colour of each scenario in pictures, from the slots the engine gave: a scenario's colour is
 * its slot's in a fixed palette (so the built-in scenarios keep theirs and a plug-in gets the next;
 * past the palette the picture picks one no one has), plus the fail-safe, the decision's own STOP
 * and "none" (before the first command), each distinct.
 */
public final class ScenarioColours {

    /** One colour per CommandArray slot. */
    private static final String[] PALETTE = {"#1f77b4", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
            "#17becf", "#bcbd22"};

    private ScenarioColours() {
    }

    /**
     * @param slots each suggesting scenario's CommandArray slot
     * @return a colour (CSS hex) by scenario name
     */
    public static Map<String, String> of(Map<String, Integer> slots) {
        Map<String, String> colours = new LinkedHashMap<>();
        slots.entrySet().stream().sorted(Map.Entry.comparingByValue()).filter(e -> e.getValue() < PALETTE.length)
                .forEach(e -> colours.put(e.getKey(), PALETTE[e.getValue()]));
        colours.put("FailSafe", "#ff7f0e");
        colours.put("DecisionMaking", "#7f7f7f");
        colours.put("none", "#c7c7c7");
        return colours;
    }
}
