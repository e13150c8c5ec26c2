package org.proactiverobotics.engine.persistence;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonParseException;
import java.lang.reflect.Modifier;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.StateStoreException;

/**
 * Turns rules and the shared memory into JSON and back, with Gson: a rule is its type (class
 * name) and its non-transient fields. Shared by every {@link StateStore}.
 */
public final class StateCodec {

    private final Gson gson = new GsonBuilder().serializeSpecialFloatingPointValues().disableHtmlEscaping().create();
    private final ClassLoader loader;

    /** A codec that loads rule types with the engine's class loader. */
    public StateCodec() {
        this(StateCodec.class.getClassLoader());
    }

    /** @param loader the class loader rule types are loaded with */
    public StateCodec(ClassLoader loader) {
        this.loader = loader;
    }

    /**
     * @param rule a rule
     * @return its type as saved: the class name
     * @throws StateStoreException when the class could not be loaded back (anonymous, local or inner)
     */
    public String ruleType(Rule rule) {
        Class<?> type = rule.getClass();
        if (type.isAnonymousClass() || type.isLocalClass()
                || (type.isMemberClass() && !Modifier.isStatic(type.getModifiers()))) {
            throw new StateStoreException("rule " + rule + " of " + type.getName()
                    + " cannot be saved: make it a top-level or static nested class");
        }
        return type.getName();
    }

    /** @return the rule's persisted fields as JSON */
    public String ruleJson(Rule rule) {
        return gson.toJson(rule);
    }

    /**
     * @param type the saved type
     * @param json the saved fields
     * @return the rule
     * @throws IllegalArgumentException naming the problem (the store adds which row)
     */
    public Rule rule(String type, String json) {
        Class<?> cls;
        try {
            cls = Class.forName(type, false, loader);
        } catch (ClassNotFoundException | LinkageError e) {
            throw new IllegalArgumentException("unknown rule type: no class " + type + " on the class path", e);
        }
        if (!Rule.class.isAssignableFrom(cls)) {
            throw new IllegalArgumentException("unknown rule type: " + type + " is not a subclass of " + Rule.class.getName());
        }
        if (Modifier.isAbstract(cls.getModifiers())) {
            throw new IllegalArgumentException("unknown rule type: " + type + " is abstract");
        }
        Object rule;
        try {
            rule = gson.fromJson(json, cls);
        } catch (JsonParseException | IllegalStateException | ClassCastException e) {
            throw new IllegalArgumentException("corrupt rule_json: " + e.getMessage(), e);
        }
        if (rule == null) {
            throw new IllegalArgumentException("corrupt rule_json: empty or null");
        }
        return (Rule) rule;
    }

    /** @return the memory as JSON */
    public String memoryJson(SharedMemory memory) {
        return gson.toJson(memory);
    }

    /**
     * @param json saved memory
     * @return the memory
     * @throws IllegalArgumentException naming the problem
     */
    public SharedMemory memory(String json) {
        SharedMemory memory;
        try {
            memory = gson.fromJson(json, SharedMemory.class);
        } catch (JsonParseException | IllegalStateException e) {
            throw new IllegalArgumentException("corrupt memory_json: " + e.getMessage(), e);
        }
        if (memory == null || memory.commandArray() == null || memory.priorityArray() == null || memory.values() == null) {
            throw new IllegalArgumentException("corrupt memory_json: empty, or missing commandArray, priorityArray or values");
        }
        if (memory.commandArray().size() != memory.priorityArray().size()) {
            throw new IllegalArgumentException("corrupt memory_json: CommandArray has " + memory.commandArray().size()
                    + " slots but PriorityArray " + memory.priorityArray().size());
        }
        Set<Integer> given = new HashSet<>();
        for (Map.Entry<String, Integer> e : memory.slots().entrySet()) {
            if (e.getKey() == null || e.getValue() == null || e.getValue() < 0 || !given.add(e.getValue())) {
                throw new IllegalArgumentException("corrupt memory_json: slots " + memory.slots()
                        + " give a scenario no slot, a negative one or one another scenario has");
            }
        }
        return memory;
    }
}
