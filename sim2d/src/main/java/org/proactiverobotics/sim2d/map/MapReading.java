package org.proactiverobotics.sim2d.map;

import java.util.List;

/**
 * A map as read: its cells, and what the reader noticed that the user should hear about (a threshold
 * that reads the unknown grey as free floor, say), one sentence each.
 *
 * @param grid  the cells, blocked or free
 * @param notes the reader's warnings, possibly none
 */
public record MapReading(OccupancyGrid grid, List<String> notes) {

    /** Keeps an unmodifiable copy of the notes. */
    public MapReading {
        notes = List.copyOf(notes);
    }
}
