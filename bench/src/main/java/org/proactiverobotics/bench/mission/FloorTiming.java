package org.proactiverobotics.bench.mission;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The engine's and the physics' cost per control step on big floors against the reference
 * arena's, measured in one JVM, round after round (the reference arena, then each floor, over the
 * direct link: no database), so that the machine's load of the moment weighs on both alike. The
 * figures are the missions' own report timings; the first round warms the JIT compiler and is
 * printed but left out of the medians. Beside them, the processor time of the thread that ran the
 * mission (the direct link runs it all on one thread: engine, physics and trace), per step, which a
 * machine loaded by other jobs inflates far less than the wall-clock timings.
 *
 * <p>{@code FloorTiming [--rounds N] [--floors 56x60,100x100] [--seed S]}
 */
public final class FloorTiming {

    private FloorTiming() {
    }

    /**
     * @param args {@code --rounds N} (default 3), {@code --floors WxH,...} (default 56x60,100x100), {@code --seed S} (default 1)
     * @throws Exception when a mission cannot run
     */
    public static void main(String[] args) throws Exception {
        int rounds = 3;
        String floors = "56x60,100x100";
        long seed = 1;
        for (int k = 0; k + 1 < args.length; k += 2) {
            switch (args[k]) {
                case "--rounds" -> rounds = Integer.parseInt(args[k + 1]);
                case "--floors" -> floors = args[k + 1];
                case "--seed" -> seed = Long.parseLong(args[k + 1]);
                default -> throw new IllegalArgumentException("unknown option " + args[k]);
            }
        }
        List<WorldSpec> worlds = new ArrayList<>();
        worlds.add(WorldFiles.bundled("reference-arena"));
        for (String f : floors.split(",")) {
            String[] wh = f.split("x");
            WorldSpec w = BigFloor.world(Double.parseDouble(wh[0]), Double.parseDouble(wh[1]), seed);
            worlds.add(w);
            System.out.printf(Locale.ROOT, "%s: %d obstacles%n", w.name(), w.obstacles().size());
        }
        double[][] engine = new double[worlds.size()][rounds];
        double[][] physics = new double[worlds.size()][rounds];
        double[][] cpu = new double[worlds.size()][rounds];
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        for (int r = 0; r < rounds; r++) {
            for (int k = 0; k < worlds.size(); k++) {
                WorldSpec w = worlds.get(k);
                Path out = Files.createTempDirectory("floor-timing-");
                MissionOptions options = new MissionOptions(w, null, null, null, "safety-first", 1).withLink(MissionOptions.Link.DIRECT);
                long cpu0 = threads.getCurrentThreadCpuTime();
                MissionReport report = new Mission(options).run(out);
                // the direct link runs the whole mission on this thread: its processor time, what the machine's load does not inflate
                cpu[k][r] = (threads.getCurrentThreadCpuTime() - cpu0) / 1e6 / report.controlSteps();
                engine[k][r] = report.timing().engineMs();
                physics[k][r] = report.timing().physicsMs();
                System.out.printf(Locale.ROOT, "round %d %-22s %-22s steps %6d  engine %.3f ms/step  physics %.4f ms/step  cpu %.3f ms/step  %.1fx real time%n",
                        r + 1, w.name(), report.outcome(), report.controlSteps(), engine[k][r], physics[k][r], cpu[k][r],
                        report.realTimeFactor());
            }
        }
        System.out.println("medians of rounds 2 on (against the reference arena's of the same rounds):");
        double refEngine = median(engine[0], rounds);
        double refPhysics = median(physics[0], rounds);
        double refCpu = median(cpu[0], rounds);
        for (int k = 0; k < worlds.size(); k++) {
            double e = median(engine[k], rounds);
            double p = median(physics[k], rounds);
            double c = median(cpu[k], rounds);
            System.out.printf(Locale.ROOT, "%-22s engine %.3f ms/step (%.2fx)  physics %.4f ms/step (%.2fx)  cpu %.3f ms/step (%.2fx)%n",
                    worlds.get(k).name(), e, e / refEngine, p, p / refPhysics, c, c / refCpu);
        }
    }

    /** The median of rounds 2 to n (all of them when there is one). */
    private static double median(double[] v, int n) {
        double[] s = java.util.Arrays.copyOfRange(v, n > 1 ? 1 : 0, n);
        java.util.Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }
}
