package org.proactiverobotics.engine.robot;

/** A scenario plug-in that cannot be used: a missing path, not a jar, no scenario, a class that cannot be loaded, a duplicate name. Bad input. */
public final class PluginException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    /** @param message what is wrong, naming the path, the class or the scenario */
    public PluginException(String message) {
        super(message);
    }
}
