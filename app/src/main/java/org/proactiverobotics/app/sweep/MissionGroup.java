package org.proactiverobotics.app.sweep;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.ToDoubleFunction;
import java.util.stream.Collectors;

/**
 * The summary's figures for one group of a sweep's missions (e.g. safety-first under small noise):
 * the success rate with its Wilson interval over every mission of the group; simulated time,
 * distance, minimum battery and recharges over the accomplished missions only (a mission that
 * dies early would otherwise look fast); collisions over the missions that ran (all but ERROR).
 *
 * @param values           the group's value of each factor it was cut by, in the factors' order
 * @param success          k accomplished of n missions
 * @param simTimeS         simulated time of the accomplished missions, seconds
 * @param distanceM        distance of the accomplished missions, metres
 * @param minBattery       lowest battery of the accomplished missions, percent
 * @param recharges        charging sessions of the accomplished missions
 * @param collisions       contacts per mission, over the missions that ran
 * @param notAccomplished  the other missions' outcomes and how many of each, most frequent first
 */
public record MissionGroup(List<String> values, SuccessRate success, MeanSd simTimeS, MeanSd distanceM,
                           MeanSd minBattery, MeanSd recharges, MeanSd collisions, Map<String, Integer> notAccomplished) {

    /**
     * A mean and sample standard deviation.
     *
     * @param count how many values
     * @param mean  their mean; NaN when there are none
     * @param sd    their sample standard deviation (n - 1); NaN below two values
     */
    public record MeanSd(int count, double mean, double sd) {

        static MeanSd of(List<SummaryHtml.Row> rows, ToDoubleFunction<SummaryHtml.Row> value) {
            int n = rows.size();
            if (n == 0) {
                return new MeanSd(0, Double.NaN, Double.NaN);
            }
            double mean = rows.stream().mapToDouble(value).sum() / n;
            double squares = rows.stream().mapToDouble(r -> Math.pow(value.applyAsDouble(r) - mean, 2)).sum();
            return new MeanSd(n, mean, n < 2 ? Double.NaN : Math.sqrt(squares / (n - 1)));
        }

        /**
         * @param decimals digits after the point
         * @return "mean ± sd", the mean alone for one value, "—" for none
         */
        public String shown(int decimals) {
            if (count == 0) {
                return SuccessRate.NONE;
            }
            String f = "%." + decimals + "f";
            return count < 2 ? String.format(Locale.ROOT, f, mean) : String.format(Locale.ROOT, f + " ± " + f, mean, sd);
        }
    }

    /**
     * @param values the group's value of each factor
     * @param rows   the group's missions
     * @return the group's figures
     */
    public static MissionGroup of(List<String> values, List<SummaryHtml.Row> rows) {
        List<SummaryHtml.Row> accomplished = rows.stream().filter(SummaryHtml.Row::success).toList();
        List<SummaryHtml.Row> ran = rows.stream().filter(r -> !r.outcome().equals(MissionResult.ERROR)).toList();
        Map<String, Long> failed = rows.stream().filter(r -> !r.success())
                .collect(Collectors.groupingBy(SummaryHtml.Row::outcome, Collectors.counting()));
        Map<String, Integer> notAccomplished = new LinkedHashMap<>();
        failed.entrySet().stream()
                .sorted(Map.Entry.<String, Long>comparingByValue().reversed().thenComparing(Map.Entry.comparingByKey()))
                .forEach(e -> notAccomplished.put(e.getKey(), e.getValue().intValue()));
        return new MissionGroup(List.copyOf(values), new SuccessRate(accomplished.size(), rows.size()),
                MeanSd.of(accomplished, SummaryHtml.Row::simTimeS), MeanSd.of(accomplished, SummaryHtml.Row::distanceM),
                MeanSd.of(accomplished, SummaryHtml.Row::minBattery), MeanSd.of(accomplished, SummaryHtml.Row::recharges),
                MeanSd.of(ran, SummaryHtml.Row::collisions), notAccomplished);
    }

    /**
     * Cuts the missions by every combination of the factors' values, each factor's values in the
     * order the sweep first ran them (its {@code --strategies} and {@code --noise} order); a
     * combination with no mission (a sweep stopped early) is kept, with n = 0.
     *
     * @param rows    the missions
     * @param factors what to cut by, outermost first
     * @return one group per combination
     */
    public static List<MissionGroup> crossed(List<SummaryHtml.Row> rows, List<Factor> factors) {
        List<SummaryHtml.Row> inOrder = rows.stream().sorted(Comparator.comparingInt(SummaryHtml.Row::index)).toList();
        List<List<String>> combinations = List.of(List.of());
        for (Factor f : factors) {
            LinkedHashSet<String> seen = new LinkedHashSet<>();
            inOrder.forEach(r -> seen.add(f.of(r)));
            List<List<String>> longer = new ArrayList<>();
            for (List<String> c : combinations) {
                for (String v : seen) {
                    List<String> next = new ArrayList<>(c);
                    next.add(v);
                    longer.add(next);
                }
            }
            combinations = longer;
        }
        List<MissionGroup> groups = new ArrayList<>(combinations.size());
        for (List<String> c : combinations) {
            List<SummaryHtml.Row> members = inOrder.stream().filter(r -> {
                for (int i = 0; i < factors.size(); i++) {
                    if (!factors.get(i).of(r).equals(c.get(i))) {
                        return false;
                    }
                }
                return true;
            }).toList();
            groups.add(of(c, members));
        }
        return groups;
    }

    /**
     * @return the other missions' outcomes as "TIME_LIMIT 3, ERROR 1" (a no-break space before each count: a
     *         line breaks only between outcomes); "—" when every mission was accomplished
     */
    public String shownNotAccomplished() {
        return notAccomplished.isEmpty() ? SuccessRate.NONE : notAccomplished.entrySet().stream()
                .map(e -> e.getKey() + "\u00A0" + e.getValue()).collect(Collectors.joining(", "));
    }
}
