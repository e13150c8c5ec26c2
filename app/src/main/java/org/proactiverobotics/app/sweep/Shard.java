package org.proactiverobotics.app.sweep;

/**
 * One of {@code count} disjoint slices of a sweep's missions: mission k (numbered from 1 in the
 * order the combinations are listed) belongs to slice {@code (k - 1) % count}. Every mission is in
 * exactly one slice whatever the count, and dealing them round-robin gives every slice a share of
 * every world, strategy and noise level (a job array's tasks then take about as long each).
 *
 * @param index which slice, from 0 (as Slurm's {@code SLURM_ARRAY_TASK_ID} and Kubernetes'
 *              {@code JOB_COMPLETION_INDEX} count)
 * @param count how many slices, at least 1
 */
public record Shard(int index, int count) {

    /** The whole sweep: one slice of one. */
    public static final Shard ALL = new Shard(0, 1);

    /** Checks the bounds. */
    public Shard {
        if (count < 1 || index < 0 || index >= count) {
            throw new IllegalArgumentException("a shard is I/N with N >= 1 and 0 <= I < N: " + index + "/" + count);
        }
    }

    /**
     * Reads a shard as the command line gives it.
     *
     * @param text {@code I/N}, e.g. {@code 0/4}
     * @return the shard
     * @throws IllegalArgumentException naming what is wrong
     */
    public static Shard parse(String text) {
        int slash = text.indexOf('/');
        if (slash < 0) {
            throw new IllegalArgumentException("expected I/N (slice I of N, I from 0 to N-1), e.g. 0/4, got " + text);
        }
        int index;
        int count;
        try {
            index = Integer.parseInt(text.substring(0, slash).trim());
            count = Integer.parseInt(text.substring(slash + 1).trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("expected I/N with two integers, e.g. 0/4, got " + text);
        }
        if (count < 1 || index < 0 || index >= count) {
            throw new IllegalArgumentException("I/N needs N >= 1 and I from 0 to N-1, got " + text);
        }
        return new Shard(index, count);
    }

    /**
     * @param missionIndex a mission's number in the sweep, from 1
     * @return whether that mission is in this slice
     */
    public boolean contains(int missionIndex) {
        return (missionIndex - 1) % count == index;
    }

    /** @return whether this is the whole sweep */
    public boolean isAll() {
        return count == 1;
    }

    @Override
    public String toString() {
        return index + "/" + count;
    }
}
