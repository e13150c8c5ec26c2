package org.proactiverobotics.app.deploy;

import java.util.TreeSet;

/** The robots an engine process serves, as given on the command line: ids and ranges ({@code 1-100}, {@code 1,3,7-9}). */
public final class RobotIds {

    /** The most robots one engine process may be given. */
    public static final int MAX = 10_000;

    private RobotIds() {
    }

    /**
     * @param spec ids and ranges separated by commas
     * @return the ids, ascending, each once
     * @throws IllegalArgumentException naming the part that is not an id or a range
     */
    public static int[] parse(String spec) {
        TreeSet<Integer> ids = new TreeSet<>();
        for (String raw : spec.split(",", -1)) {
            String part = raw.strip();
            int dash = part.indexOf('-', 1);
            long from;
            long to;
            try {
                from = Integer.parseInt(dash < 0 ? part : part.substring(0, dash).strip());
                to = dash < 0 ? from : Integer.parseInt(part.substring(dash + 1).strip());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(problem(spec, part));
            }
            if (from < 0 || to < from) {
                throw new IllegalArgumentException(problem(spec, part));
            }
            if (to - from + 1 > MAX) {
                throw new IllegalArgumentException("--robot-ids: more than " + MAX + " robots in '" + spec + "'");
            }
            for (long id = from; id <= to; id++) { // long: a range up to Integer.MAX_VALUE ends
                ids.add((int) id);
            }
            if (ids.size() > MAX) {
                throw new IllegalArgumentException("--robot-ids: more than " + MAX + " robots in '" + spec + "'");
            }
        }
        return ids.stream().mapToInt(Integer::intValue).toArray();
    }

    /**
     * @param ids robot ids, ascending
     * @return them as ids and ranges, e.g. {@code 1-3,7} (empty for none)
     */
    public static String format(int[] ids) {
        StringBuilder out = new StringBuilder();
        for (int k = 0; k < ids.length; ) {
            int end = k;
            while (end + 1 < ids.length && ids[end + 1] == ids[end] + 1) {
                end++;
            }
            out.append(out.length() == 0 ? "" : ",").append(ids[k]);
            if (end > k) {
                out.append('-').append(ids[end]);
            }
            k = end + 1;
        }
        return out.toString();
    }

    private static String problem(String spec, String part) {
        return "--robot-ids: '" + part + "' in '" + spec + "' is not a robot id (>= 0) or a range FROM-TO with"
                + " FROM <= TO (e.g. 1-100 or 1,3,7-9)";
    }
}
