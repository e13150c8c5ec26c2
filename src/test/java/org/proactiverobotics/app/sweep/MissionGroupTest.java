package org.proactiverobotics.app.sweep;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The summary's groups: rates over every mission, times and distances over the accomplished ones, every combination kept. */
class MissionGroupTest {

    private static SummaryHtml.Row row(int index, String world, String strategy, String noise, String outcome, double simTimeS,
                                       double distanceM, int collisions) {
        boolean ok = outcome.equals("MISSION_ACCOMPLISHED");
        return new SummaryHtml.Row(index, world, strategy, noise, 1, outcome, ok, ok ? "2/2" : "0/2", simTimeS, 0.5, distanceM,
                collisions, 50, 0, ok ? "" : "why", null);
    }

    @Test
    void timesAndDistancesCountOnlyAccomplishedMissionsCollisionsEveryMissionThatRan() {
        List<SummaryHtml.Row> rows = List.of(
                row(1, "a", "s", "none", "MISSION_ACCOMPLISHED", 100, 20, 0),
                row(2, "a", "s", "none", "MISSION_ACCOMPLISHED", 120, 24, 0),
                row(3, "a", "s", "none", "BATTERY_DEPLETED", 3, 1, 2),
                row(4, "a", "s", "none", "ERROR", 0, 0, 0));
        MissionGroup g = MissionGroup.of(List.of("s"), rows);
        assertThat(g.success()).isEqualTo(new SuccessRate(2, 4));
        assertThat(g.simTimeS().mean()).isEqualTo(110.0); // the battery's 3 s would make it 74.3
        assertThat(g.simTimeS().sd()).isCloseTo(Math.sqrt(200), within(1e-12));
        assertThat(g.distanceM().shown(1)).isEqualTo("22.0 ± 2.8");
        assertThat(g.collisions().mean()).isCloseTo(2 / 3.0, within(1e-12)); // the ERROR never ran
        assertThat(g.shownNotAccomplished()).isEqualTo("BATTERY_DEPLETED\u00A01, ERROR\u00A01");
    }

    @Test
    void aGroupWithNothingAccomplishedShowsDashes() {
        MissionGroup g = MissionGroup.of(List.of("s"), List.of(row(1, "a", "s", "none", "TIME_LIMIT", 3, 1, 0)));
        assertThat(g.success().shownInterval()).isEqualTo("0.0–79.3");
        assertThat(g.simTimeS().shown(1)).isEqualTo("—");
        assertThat(g.distanceM().shown(1)).isEqualTo("—");
    }

    @Test
    void crossedKeepsEveryCombinationInTheSweepsOrderEvenWithoutMissions() {
        List<SummaryHtml.Row> rows = List.of(
                row(1, "rooms-001", "safety-first", "none", "MISSION_ACCOMPLISHED", 10, 1, 0),
                row(2, "rooms-001", "safety-first", "small", "TIME_LIMIT", 10, 1, 0),
                row(3, "rooms-001", "destination-first", "none", "MISSION_ACCOMPLISHED", 10, 1, 0),
                row(5, "reference-arena", "safety-first", "none", "MISSION_ACCOMPLISHED", 10, 1, 0));
        List<MissionGroup> groups = MissionGroup.crossed(rows, List.of(Factor.STRATEGY, Factor.NOISE));
        assertThat(groups).extracting(MissionGroup::values).containsExactly(List.of("safety-first", "none"),
                List.of("safety-first", "small"), List.of("destination-first", "none"), List.of("destination-first", "small"));
        assertThat(groups).extracting(g -> g.success().shownCount()).containsExactly("2/2", "0/1", "1/1", "0/0");
        assertThat(groups.get(3).success().shownInterval()).isEqualTo("—");
        assertThat(MissionGroup.crossed(rows, List.of(Factor.KIND))).extracting(MissionGroup::values)
                .containsExactly(List.of("rooms"), List.of("—"));
    }
}
