package org.proactiverobotics.engine;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Proactive Engine: runs rules iteration by iteration over two FIFO queues,
 * {@code currentQueue} and {@code nextQueue}.
 *
 * <p>An iteration moves every rule of nextQueue into currentQueue, then runs the rules from the
 * head of currentQueue one at a time until it is empty; every rule generated meanwhile is
 * appended to nextQueue in generation order. Rules submitted from outside go to nextQueue. At the
 * end the iteration number, nextQueue, the shared memory and the iteration's failures are saved
 * in one transaction by the {@link StateStore}.
 *
 * <pre>{@code
 * ProactiveEngine engine = ProactiveEngine.builder()
 *         .robotId(1)
 *         .algorithm(Algorithm.LAZY)
 *         .store(new JdbcStateStore(dataSource))                             // from engine.persistence
 *         .service(SensorDao.class, new SensorDao(dataSource))
 *         .build();
 * engine.start(new StartUp(List.of("DataAcquisition", "BatteryMonitor")));  // resumes when a state is saved
 * engine.runIteration();                                                      // once per control period
 * }</pre>
 *
 * <p>{@link #runIteration()} and the start methods belong to one thread at a time;
 * {@link #submit} may be called from any thread.
 */
public final class ProactiveEngine {

    private static final Logger LOG = LoggerFactory.getLogger(ProactiveEngine.class);
    private static final Part[] PARTS = Part.values();

    private final int robotId;
    private final Algorithm algorithm;
    private final StateStore store;
    private final int memorySlots;
    private final IterationListener[] listeners;
    private final RuleContext context;
    private final Map<String, Integer> preferredSlots;

    private ArrayDeque<Rule> currentQueue = new ArrayDeque<>();
    private ArrayDeque<Rule> nextQueue = new ArrayDeque<>();
    // Outside submissions wait here so that a failed rule's generated rules can be rolled back from nextQueue's tail.
    private final ConcurrentLinkedQueue<Rule> submitted = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean iterating = new AtomicBoolean();

    private SharedMemory memory;
    private long iteration;
    private boolean started;
    private boolean resumed;
    private List<RuleFailure> lastFailures = List.of();
    private final ArrayList<RuleFailure> failures = new ArrayList<>();
    private final FailureLog failureLog = new FailureLog();
    private final List<RuleFailure> failuresView = Collections.unmodifiableList(failures);

    private Rule running;                 // the rule whose part runs, for RuleContext.suggest
    private final Map<Class<?>, Boolean> saveable = new HashMap<>();
    private int generatedCount;
    private int partsRun;                 // bit set of Part ordinals of the rule running
    private ArrayList<Rule> traceGenerated; // non-null only while a listener traces a rule

    private ProactiveEngine(Builder b) {
        this.robotId = b.robotId;
        this.algorithm = b.algorithm;
        this.store = b.store;
        this.memorySlots = b.memorySlots;
        this.listeners = b.listeners.toArray(IterationListener[]::new);
        this.context = new RuleContext(this, Map.copyOf(b.services));
        this.preferredSlots = new LinkedHashMap<>(b.slots);
        this.memory = new SharedMemory(memorySlots);
    }

    /** @return a builder; every setting has a default (robot 1, standard algorithm, no persistence) */
    public static Builder builder() {
        return new Builder();
    }

    // ---------------------------------------------------------------- start

    /**
     * Resumes from the last saved state when the store holds one, else starts fresh with the
     * given rules in nextQueue (typically one {@link StartUp}).
     *
     * @param initialRules the rules of iteration 1 on a fresh start; ignored on a resume
     * @throws CorruptStateException when the saved state cannot be read (never a silent fresh start)
     */
    public void start(Rule... initialRules) {
        start(0, initialRules);
    }

    /**
     * {@link #start(Rule...)} whose iterations, on a fresh start, go on from a given number (see
     * {@link #startFresh(long, Rule...)}).
     *
     * @param afterIteration the iteration a fresh start's first one follows (0 for a new run)
     * @param initialRules   the rules of the first iteration on a fresh start; ignored on a resume
     * @throws CorruptStateException when the saved state cannot be read (never a silent fresh start)
     */
    public void start(long afterIteration, Rule... initialRules) {
        Optional<SavedState> saved = store.load(robotId);
        if (saved.isPresent()) {
            SavedState state = saved.get();
            reset(state.iteration(), state.memory(), state.nextQueue());
            lastFailures = List.copyOf(state.lastFailures());
            resumed = true;
            LOG.info("engine {} resumed after iteration {} with {} rules in nextQueue", robotId, iteration, nextQueue.size());
        } else {
            reset(afterIteration, new SharedMemory(memorySlots), List.of(initialRules));
            LOG.info("engine {} started fresh (no saved state){}", robotId,
                    afterIteration == 0 ? "" : ", iterations going on after " + afterIteration);
        }
    }

    /**
     * Starts fresh, explicitly: clears any saved state of this engine instance, then puts the
     * given rules in nextQueue for iteration 1.
     *
     * @param initialRules the rules of iteration 1
     */
    public void startFresh(Rule... initialRules) {
        startFresh(0, initialRules);
    }

    /**
     * {@link #startFresh(Rule...)} whose iterations go on from a given number, for a fresh start
     * in the middle of a robot's run: the robot ignores commands of iterations earlier than one it
     * already ran, so numbering must not go back.
     *
     * @param afterIteration the iteration the first one follows (0 for a new run)
     * @param initialRules   the rules of the first iteration
     */
    public void startFresh(long afterIteration, Rule... initialRules) {
        store.clear(robotId);
        reset(afterIteration, new SharedMemory(memorySlots), List.of(initialRules));
        LOG.info("engine {} started fresh (saved state cleared){}", robotId,
                afterIteration == 0 ? "" : ", iterations going on after " + afterIteration);
    }

    private void reset(long iteration, SharedMemory memory, List<Rule> rules) {
        if (iterating.get()) {
            throw new IllegalStateException("cannot start the engine while an iteration runs");
        }
        this.iteration = iteration;
        this.memory = memory;
        memory.assignSlots(preferredSlots);
        this.currentQueue.clear();
        this.nextQueue.clear();
        this.nextQueue.addAll(rules);
        this.lastFailures = List.of();
        this.failures.clear();
        this.resumed = false;
        this.started = true;
    }

    // ---------------------------------------------------------------- iterate

    /**
     * Submits a rule from outside; thread-safe. It joins nextQueue, after the rules generated in
     * the running iteration (if any), and so runs in the next iteration to start.
     *
     * @param rule the rule
     */
    public void submit(Rule rule) {
        submitted.add(Objects.requireNonNull(rule, "submitted rule"));
    }

    /**
     * Runs one iteration, saves the state and returns its figures. Whoever drives the engine calls
     * it once per control period (in the robot mission, {@code engine.robot.RobotEngine}).
     *
     * @return the iteration's summary
     * @throws StateStoreException when saving fails (the iteration itself has run)
     */
    public IterationSummary runIteration() {
        if (!started) {
            throw new IllegalStateException("start the engine (start or startFresh) before running iterations");
        }
        if (!iterating.compareAndSet(false, true)) {
            throw new IllegalStateException("an iteration is already running; runIteration is single-threaded");
        }
        try {
            return iterate();
        } finally {
            iterating.set(false);
        }
    }

    private IterationSummary iterate() {
        long start = System.nanoTime();
        int submittedCount = drainSubmitted();
        ArrayDeque<Rule> empty = currentQueue; // the queues swap: nextQueue becomes currentQueue and nextQueue is empty
        currentQueue = nextQueue;
        nextQueue = empty;
        iteration++;
        failures.clear();
        generatedCount = 0;
        boolean tracing = listeners.length > 0;
        if (tracing) {
            int queued = currentQueue.size();
            notifyListeners(l -> l.iterationStarted(iteration, queued));
        }
        int run = 0;
        int failed = 0;
        Rule rule;
        while ((rule = currentQueue.pollFirst()) != null) {
            Outcome outcome = tracing ? runTraced(rule, run) : runRule(rule);
            if (outcome == Outcome.FAILED) {
                failed++;
            }
            run++;
        }
        submittedCount += drainSubmitted();
        long saveStart = System.nanoTime();
        store.save(robotId, iteration, nextQueue, memory, failuresView);
        long end = System.nanoTime();
        lastFailures = failures.isEmpty() ? List.of() : List.copyOf(failures);
        IterationSummary summary = new IterationSummary(iteration, run, generatedCount, failed, submittedCount,
                nextQueue.size(), end - start, end - saveStart);
        if (tracing) {
            notifyListeners(l -> l.iterationEnded(summary));
        }
        return summary;
    }

    private int drainSubmitted() {
        int n = 0;
        Rule rule;
        while ((rule = submitted.poll()) != null) {
            nextQueue.addLast(rule);
            n++;
        }
        return n;
    }

    /** Runs the five parts in the algorithm's order; the hot path: allocates nothing unless a part throws. */
    private Outcome runRule(Rule rule) {
        int queueMark = nextQueue.size();
        int generatedMark = generatedCount;
        RuleContext ctx = context;
        running = rule;
        Part part = Part.GUARD_DATA_ACQUISITION;
        partsRun = 1 << Part.GUARD_DATA_ACQUISITION.ordinal();
        try {
            rule.acquireGuardData(ctx);
            if (algorithm == Algorithm.STANDARD) {
                part = mark(Part.CONDITION_DATA_ACQUISITION);
                rule.acquireConditionData(ctx);
            }
            part = mark(Part.ACTIVATION_GUARDS);
            Outcome outcome;
            if (!rule.activationGuards(ctx)) {
                outcome = Outcome.NOT_ACTIVATED;
            } else {
                if (algorithm == Algorithm.LAZY) {
                    part = mark(Part.CONDITION_DATA_ACQUISITION);
                    rule.acquireConditionData(ctx);
                }
                part = mark(Part.CONDITIONS);
                if (!rule.conditions(ctx)) {
                    outcome = Outcome.CONDITIONS_FALSE;
                } else {
                    part = mark(Part.ACTIONS);
                    rule.actions(ctx);
                    outcome = Outcome.ACTIONS_RUN;
                }
            }
            part = mark(Part.RULES_GENERATION);
            rule.rulesGeneration(ctx, outcome);
            return outcome;
        } catch (Exception | LinkageError | StackOverflowError | AssertionError e) {
            // A rule's fault, whatever it throws short of the JVM failing: the failed rule generates nothing.
            while (nextQueue.size() > queueMark) {
                nextQueue.pollLast();
            }
            generatedCount = generatedMark;
            RuleFailure failure = RuleFailure.of(iteration, rule, part, e);
            failures.add(failure);
            failureLog.failed(failure, e);
            return Outcome.FAILED;
        } finally {
            running = null;
        }
    }

    private Part mark(Part part) {
        partsRun |= 1 << part.ordinal();
        return part;
    }

    private Outcome runTraced(Rule rule, int position) {
        ArrayList<Rule> generated = new ArrayList<>(2);
        traceGenerated = generated;
        Outcome outcome;
        try {
            outcome = runRule(rule);
        } finally {
            traceGenerated = null;
        }
        RuleFailure failure = null;
        if (outcome == Outcome.FAILED) {
            generated.clear();
            RuleFailure f = failures.get(failures.size() - 1);
            notifyListeners(l -> l.ruleFailed(f));
            failure = f;
        }
        List<Part> parts = new ArrayList<>(PARTS.length);
        for (Part p : PARTS) {
            if ((partsRun & (1 << p.ordinal())) != 0) {
                parts.add(p);
            }
        }
        if (algorithm == Algorithm.LAZY && parts.contains(Part.CONDITION_DATA_ACQUISITION)) {
            // Lazy runs condition data after the guards: list the parts in the order they ran.
            parts.remove(Part.CONDITION_DATA_ACQUISITION);
            parts.add(parts.indexOf(Part.ACTIVATION_GUARDS) + 1, Part.CONDITION_DATA_ACQUISITION);
        }
        RuleTrace trace = new RuleTrace(iteration, position, rule, List.copyOf(parts), outcome, failure, List.copyOf(generated));
        notifyListeners(l -> l.ruleRan(trace));
        return outcome;
    }

    private void notifyListeners(Consumer<IterationListener> call) {
        for (IterationListener listener : listeners) {
            try {
                call.accept(listener);
            } catch (RuntimeException e) {
                // A broken observer must not stop the rules.
                LOG.warn("iteration listener {} threw", listener, e);
            }
        }
    }

    void generate(Rule rule) {
        if (store != NoStateStore.INSTANCE) {
            checkSaveable(rule);
        }
        nextQueue.addLast(rule);
        generatedCount++;
        if (traceGenerated != null) {
            traceGenerated.add(rule);
        }
    }

    /** A rule the store cannot save fails the rule that generates it, not the iteration's save; checked once per class. */
    private void checkSaveable(Rule rule) {
        Boolean ok = saveable.get(rule.getClass());
        if (ok == null) {
            try {
                store.checkSaveable(rule);
                ok = Boolean.TRUE;
            } catch (RuntimeException e) {
                ok = Boolean.FALSE;
                LOG.warn("rule type {} cannot be saved with the engine state: {}", rule.getClass().getName(), e.getMessage());
            }
            saveable.put(rule.getClass(), ok);
        }
        if (!ok) {
            throw new IllegalArgumentException("rule " + rule + " (" + rule.getClass().getName()
                    + ") cannot be saved with the engine state: make it a top-level or static nested class whose"
                    + " non-transient fields Gson can write (numbers, strings, arrays, lists, maps, records of them)");
        }
    }

    /** The CommandArray slot of the running rule's scenario; for {@link RuleContext#suggest}. */
    int slotOfRunningRule() {
        Rule rule = running;
        if (rule == null) {
            throw new IllegalStateException("suggest is for a rule's parts, while the rule runs");
        }
        int slot = memory.slotOf(rule.scenario());
        if (slot < 0) {
            throw new IllegalStateException("scenario '" + rule.scenario() + "' of rule " + rule.name()
                    + " has no CommandArray slot (slots: " + memory.slots() + ")");
        }
        return slot;
    }

    /** @return the rule whose part is running, or null between rules */
    Rule runningRule() {
        return running;
    }

    // ---------------------------------------------------------------- read

    /** @return the number of the last iteration run (0 before the first); during an iteration, the running one */
    public long iteration() {
        return iteration;
    }

    /** @return the engine instance id, the {@code robot_id} of its saved state */
    public int robotId() {
        return robotId;
    }

    /** @return the algorithm this engine runs */
    public Algorithm algorithm() {
        return algorithm;
    }

    /** @return true when the last start resumed a saved state */
    public boolean resumed() {
        return resumed;
    }

    /** @return the memory scenarios share; touch it from the engine thread only */
    public SharedMemory memory() {
        return memory;
    }

    /** @return a copy of nextQueue, head first (submissions not yet drained excluded); engine thread only */
    public List<Rule> nextQueue() {
        return List.copyOf(nextQueue);
    }

    /** @return the number of rules in nextQueue */
    public int nextQueueSize() {
        return nextQueue.size();
    }

    /** @return the failures of the last completed iteration */
    public List<RuleFailure> lastIterationFailures() {
        return lastFailures;
    }

    /** Engine thread only: a linear look through the queues (about ten rules), asked only after a failure. */
    boolean scheduled(String scenario) {
        return scheduled(scenario, null);
    }

    /** Whether a rule of this scenario (and of this name, unless null) is running or queued. */
    boolean scheduled(String scenario, String name) {
        return any(currentQueue, scenario, name) || any(nextQueue, scenario, name) || any(submitted, scenario, name);
    }

    private static boolean any(Iterable<Rule> rules, String scenario, String name) {
        for (Rule r : rules) {
            if (scenario.equals(r.scenario()) && (name == null || name.equals(r.name()))) {
                return true;
            }
        }
        return false;
    }

    List<RuleFailure> previousFailures() {
        return lastFailures;
    }

    List<RuleFailure> currentFailures() {
        return failuresView;
    }

    // ---------------------------------------------------------------- build

    /** Configures a {@link ProactiveEngine}. */
    public static final class Builder {
        private int robotId = 1;
        private Algorithm algorithm = Algorithm.STANDARD;
        private StateStore store = StateStore.none();
        private int memorySlots = SharedMemory.DEFAULT_SLOTS;
        private final List<IterationListener> listeners = new ArrayList<>();
        private final Map<Class<?>, Object> services = new LinkedHashMap<>();
        private final Map<String, Integer> slots = new LinkedHashMap<>();

        private Builder() {
        }

        /**
         * Gives a scenario a CommandArray slot at start, for {@link RuleContext#suggest}: the lowest
         * free one, in the order scenarios are given. A saved state's slots are kept on a resume.
         *
         * @param scenario the scenario's name
         */
        public Builder slot(String scenario) {
            return slot(scenario, -1);
        }

        /**
         * As {@link #slot(String)}, with the slot it gets when that one is free: how the built-in
         * scenarios keep the slots they always had.
         *
         * @param scenario      the scenario's name
         * @param preferredSlot its slot when free, or -1 for the lowest free one
         */
        public Builder slot(String scenario, int preferredSlot) {
            slots.putIfAbsent(Objects.requireNonNull(scenario, "scenario"), preferredSlot);
            return this;
        }

        /** @param robotId the engine instance id, the {@code robot_id} its state is saved under */
        public Builder robotId(int robotId) {
            this.robotId = robotId;
            return this;
        }

        /** @param algorithm standard (default) or lazy data acquisition */
        public Builder algorithm(Algorithm algorithm) {
            this.algorithm = Objects.requireNonNull(algorithm);
            return this;
        }

        /** @param store where the state is saved each iteration; {@link StateStore#none()} by default */
        public Builder store(StateStore store) {
            this.store = Objects.requireNonNull(store);
            return this;
        }

        /** @param slots n, the size of the CommandArray and PriorityArray on a fresh start (default 8) */
        public Builder memorySlots(int slots) {
            if (slots < 1) {
                throw new IllegalArgumentException("memory slots must be at least 1: " + slots);
            }
            this.memorySlots = slots;
            return this;
        }

        /** @param listener observes every iteration (traces are built only when one is registered) */
        public Builder listener(IterationListener listener) {
            listeners.add(Objects.requireNonNull(listener));
            return this;
        }

        /**
         * Registers a service rules find with {@link RuleContext#service}; services are not
         * saved, so a resumed engine gets them from its builder.
         */
        public <T> Builder service(Class<T> type, T service) {
            services.put(Objects.requireNonNull(type), type.cast(Objects.requireNonNull(service)));
            return this;
        }

        /** @return the engine, not started yet */
        public ProactiveEngine build() {
            return new ProactiveEngine(this);
        }
    }
}
