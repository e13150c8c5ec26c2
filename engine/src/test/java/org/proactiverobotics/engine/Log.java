package org.proactiverobotics.engine;

import java.util.ArrayList;
import java.util.List;

/** A test service rules write what they do to; services keep rules free of non-saved fields. */
final class Log {

    final List<String> events = new ArrayList<>();

    void add(String event) {
        events.add(event);
    }

    List<String> take() {
        List<String> copy = List.copyOf(events);
        events.clear();
        return copy;
    }
}
