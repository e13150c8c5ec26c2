package org.proactiverobotics.app.sweep;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/** {@link WorldJson}: a world written back to its file reads as the same world, with one robot or several. */
class WorldJsonTest {

    private static final WorldSpec.Robot WIDE = new WorldSpec.Robot(3.5, 1.0, 180.0, 0.2, 0.4, 1.5, List.of(-45.0, 0.0, 45.0));

    private static WorldSpec fleet() {
        WorldSpec one = WorldFiles.bundled("reference-arena");
        List<WorldSpec.RobotEntry> robots = List.of(
                new WorldSpec.RobotEntry(3, one.robot(), one.checkpoints()),
                new WorldSpec.RobotEntry(8, WIDE, List.of(new WorldSpec.Checkpoint(-3.5, 1.0), new WorldSpec.Checkpoint(0.0, 3.5))));
        return WorldSpec.fleet("two-robots", 32, 300.0, 4L, one.arena(), robots, one.obstacles(), 0.3,
                List.of(one.rechargeStation(), new WorldSpec.RechargeStation(3.0, -3.0, 0.4)), one.battery());
    }

    @Test
    void aFleetWorldRoundTripsWithItsRobotsAndStations() {
        WorldSpec fleet = fleet();
        String json = WorldJson.of(fleet);
        assertThat(json).contains("\"robots\": [", "\"id\": 8", "\"rechargeStations\": [", "\"sensorAnglesDeg\": [")
                .doesNotContain("\"robot\":", "\"rechargeStation\":");
        WorldSpec back = WorldFiles.parse(json);
        assertThat(back).isEqualTo(fleet);
        assertThat(WorldJson.of(back)).isEqualTo(json);
        // a new seed keeps every robot and station
        WorldSpec reseeded = WorldJson.withSeed(fleet, 99);
        assertThat(reseeded.seed()).isEqualTo(99);
        assertThat(reseeded.robots()).isEqualTo(fleet.robots());
        assertThat(reseeded.rechargeStations()).isEqualTo(fleet.rechargeStations());
    }

    @Test
    void aOneRobotWorldIsWrittenAsItAlwaysWas() {
        WorldSpec one = WorldFiles.bundled("reference-arena");
        String json = WorldJson.of(one);
        assertThat(json).contains("\"robot\": {", "\"checkpoints\": [", "\"rechargeStation\": {")
                .doesNotContain("robots", "rechargeStations", "\"id\"");
        assertThat(WorldFiles.parse(json)).isEqualTo(one);
        // a robots list of one robot with id 1 is the one-robot world, and is written as one
        WorldSpec listed = WorldSpec.fleet(one.name(), one.timeStepMs(), one.maxSimTimeS(), one.seed(), one.arena(),
                List.of(new WorldSpec.RobotEntry(1, one.robot(), one.checkpoints())), one.obstacles(), one.checkpointRadiusM(),
                List.of(one.rechargeStation()), one.battery());
        assertThat(listed).isEqualTo(one);
        assertThat(WorldJson.of(listed)).isEqualTo(json);
    }

    @Test
    void aLoneRobotWithAnotherIdKeepsItsIdAndSeveralStationsStayAList() {
        WorldSpec one = WorldFiles.bundled("reference-arena");
        WorldSpec lone = WorldSpec.fleet(one.name(), one.timeStepMs(), one.maxSimTimeS(), one.seed(), one.arena(),
                List.of(new WorldSpec.RobotEntry(5, one.robot(), one.checkpoints())), one.obstacles(), one.checkpointRadiusM(),
                List.of(one.rechargeStation(), new WorldSpec.RechargeStation(3.0, -3.0, 0.4)), one.battery());
        WorldSpec back = WorldFiles.parse(WorldJson.of(lone));
        assertThat(back).isEqualTo(lone);
        assertThat(back.robots().get(0).id()).isEqualTo(5);
    }
}
