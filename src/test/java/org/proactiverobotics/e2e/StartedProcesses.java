package org.proactiverobotics.e2e;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

/**
 * Every OS process the tests start, and the one way they end them: a process and its whole tree
 * (the descendants it has now, and every descendant seen while it ran, so that a child its parent
 * left behind, as a bash script that failed under {@code set -e} leaves its background jobs, is
 * ended too) get SIGTERM, then SIGKILL after {@link #GRACE}, and are waited for.
 *
 * <p>Start a process with {@link #start(ProcessBuilder)}. {@link EndsStartedProcesses} (a JUnit
 * extension every test of this module gets, see junit-platform.properties) ends what a test
 * started once the test is over, however it ended: passed, failed, threw, or timed out. A
 * shutdown hook ends whatever is left, and every other child of the test JVM, when the JVM
 * itself is stopped (Ctrl-C, SIGTERM); only a SIGKILL of the test JVM escapes it.
 */
final class StartedProcesses {

    /** How long a process may take to end on SIGTERM (an engine saves its state) before SIGKILL. */
    static final Duration GRACE = Duration.ofSeconds(5);
    /** How long to wait for a SIGKILLed process to be gone. */
    private static final Duration KILL_WAIT = Duration.ofSeconds(10);
    /** How often the trees of the running processes are looked at, ms: a child seen once is never lost. */
    private static final long WATCH_EVERY_MS = 100;

    /** One started process and every descendant seen while it ran. */
    private static final class Tree {
        final ProcessHandle root;
        final Set<ProcessHandle> seen = new LinkedHashSet<>();

        Tree(ProcessHandle root) {
            this.root = root;
        }

        synchronized void look() {
            if (root.isAlive()) {
                root.descendants().forEach(seen::add);
            }
        }

        synchronized List<ProcessHandle> handles() {
            look();
            List<ProcessHandle> all = new ArrayList<>();
            all.add(root);
            all.addAll(seen);
            return all;
        }
    }

    private static final List<Tree> STARTED = new ArrayList<>();
    private static final ScheduledExecutorService WATCH = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "started-processes-watch");
        t.setDaemon(true);
        return t;
    });

    static {
        WATCH.scheduleWithFixedDelay(StartedProcesses::lookAtAll, WATCH_EVERY_MS, WATCH_EVERY_MS, TimeUnit.MILLISECONDS);
        Runtime.getRuntime().addShutdownHook(new Thread(StartedProcesses::endEverything, "started-processes-end"));
    }

    private StartedProcesses() {
    }

    /**
     * Starts a process and registers it, to be ended with its tree when the test is over.
     *
     * @param builder what to start
     * @return the started process
     * @throws IOException as {@link ProcessBuilder#start()} throws it
     */
    static Process start(ProcessBuilder builder) throws IOException {
        synchronized (STARTED) {
            Process p = builder.start();
            STARTED.add(new Tree(p.toHandle()));
            return p;
        }
    }

    /**
     * Registers a process something else started (a library's driver process), to be ended with
     * its tree as those from {@link #start} are.
     *
     * @param handle the process
     */
    static void register(ProcessHandle handle) {
        synchronized (STARTED) {
            STARTED.add(new Tree(handle));
        }
    }

    /** @return a mark: {@link #endStartedSince} ends the processes started after it */
    static int mark() {
        synchronized (STARTED) {
            return STARTED.size();
        }
    }

    /**
     * Ends the processes started since the mark, each with its tree, and forgets them.
     *
     * @param mark from {@link #mark()}
     * @return the processes of those trees that were still running
     */
    static List<ProcessHandle> endStartedSince(int mark) {
        List<Tree> trees;
        synchronized (STARTED) {
            List<Tree> since = STARTED.subList(Math.min(mark, STARTED.size()), STARTED.size());
            trees = new ArrayList<>(since);
            since.clear();
        }
        List<ProcessHandle> handles = new ArrayList<>();
        trees.forEach(t -> handles.addAll(t.handles()));
        return endAll(handles);
    }

    /**
     * Ends started processes with their trees (SIGTERM, SIGKILL after {@link #GRACE}) and waits
     * until they are gone; a test that must stop its processes at a point of its own (before it
     * drops their database, say) calls this.
     *
     * @param processes processes from {@link #start}, or any others
     * @return the processes of their trees that were still running
     */
    static List<ProcessHandle> end(Collection<Process> processes) {
        List<ProcessHandle> handles = new ArrayList<>();
        for (Process process : processes) {
            Tree tree;
            synchronized (STARTED) {
                ProcessHandle handle = process.toHandle();
                tree = STARTED.stream().filter(t -> t.root.equals(handle)).findFirst().orElseGet(() -> new Tree(handle));
            }
            handles.addAll(tree.handles());
        }
        return endAll(handles);
    }

    /**
     * {@link #end(Collection)} for one process.
     *
     * @param process a process from {@link #start}, or any other
     * @return the processes of its tree that were still running
     */
    static List<ProcessHandle> end(Process process) {
        return end(List.of(process));
    }

    /**
     * Ends the processes: SIGTERM to all at once, SIGKILL to those still running after
     * {@link #GRACE}, then waits for them.
     *
     * @return those that were running
     */
    private static List<ProcessHandle> endAll(List<ProcessHandle> handles) {
        List<ProcessHandle> alive = handles.stream().filter(ProcessHandle::isAlive).distinct().toList();
        alive.forEach(ProcessHandle::destroy);
        awaitGone(alive, GRACE);
        alive.stream().filter(ProcessHandle::isAlive).forEach(ProcessHandle::destroyForcibly);
        awaitGone(alive, KILL_WAIT);
        List<ProcessHandle> left = alive.stream().filter(ProcessHandle::isAlive).toList();
        if (!left.isEmpty()) {
            System.err.println("StartedProcesses: still running after SIGKILL: "
                    + left.stream().map(h -> String.valueOf(h.pid())).collect(Collectors.joining(", ")));
        }
        return alive;
    }

    private static void awaitGone(List<ProcessHandle> handles, Duration within) {
        long deadline = System.nanoTime() + within.toNanos();
        for (ProcessHandle h : handles) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return;
            }
            try {
                h.onExit().get(left, TimeUnit.NANOSECONDS);
            } catch (java.util.concurrent.TimeoutException e) {
                return;
            } catch (java.util.concurrent.ExecutionException e) {
                // onExit does not fail for a process; nothing to wait for
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private static void lookAtAll() {
        List<Tree> trees;
        synchronized (STARTED) {
            trees = new ArrayList<>(STARTED);
        }
        trees.forEach(Tree::look);
    }

    /** The shutdown hook: every registered tree, then every other child of this JVM (a browser's driver). */
    private static void endEverything() {
        List<ProcessHandle> handles = new ArrayList<>();
        List<Tree> trees;
        synchronized (STARTED) {
            trees = new ArrayList<>(STARTED);
            STARTED.clear();
        }
        trees.forEach(t -> handles.addAll(t.handles()));
        ProcessHandle.current().descendants().forEach(handles::add);
        endAll(handles);
    }
}
