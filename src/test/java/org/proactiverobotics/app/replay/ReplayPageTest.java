package org.proactiverobotics.app.replay;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The replay page's template: a one-robot page has none of the fleet's parts (and so stays what it was before
 * fleets, which the byte-for-byte comparison against main's jar checks), a fleet's page has them all, and the
 * data says which it is.
 */
class ReplayPageTest {

    private static WorldSpec twoRobots() {
        List<WorldSpec.RobotEntry> robots = List.of(
                new WorldSpec.RobotEntry(1, new WorldSpec.Robot(-1.0, 0.0, 0.0, 0.12, 0.5, 1.0),
                        List.of(new WorldSpec.Checkpoint(1.0, 0.0))),
                new WorldSpec.RobotEntry(7, new WorldSpec.Robot(1.0, 1.0, 180.0, 0.15, 0.5, 1.0),
                        List.of(new WorldSpec.Checkpoint(-1.0, 1.0), new WorldSpec.Checkpoint(0.0, -1.0))));
        return WorldSpec.fleet("two", 32, 10.0, 1, new WorldSpec.Arena(3.0), robots, List.of(), 0.25,
                List.of(new WorldSpec.RechargeStation(-2.0, 2.0, 0.3), new WorldSpec.RechargeStation(2.0, -2.0, 0.3)),
                WorldSpec.Battery.DEFAULT);
    }

    @Test
    void aOneRobotPageHasNoneOfTheFleetsParts() {
        String page = ReplayPage.html(ReplayPage.header(ReplayPage.Source.RUN, null, Map.of(), "", new ReplayData(Map.of()).toJson(0)));
        assertThat(page).doesNotContain("FLEET").doesNotContain("id=\"robot\"").doesNotContain("robotHash")
                .contains("\"#iteration=\" + S.iteration[cur]");
        assertThat(ReplayPage.template(false)).isEqualTo(page.substring(0, page.indexOf("{\"source\"")) + "/*REPLAY_DATA*/null"
                + page.substring(page.indexOf("</script>", page.indexOf("{\"source\""))));
    }

    @Test
    void aFleetsPageCarriesEveryRobotItsOwnBodyAndCheckpointsAndEveryStation() {
        WorldSpec world = twoRobots();
        JsonObject data = ReplayPage.header(ReplayPage.Source.RUN, world, Map.of(), "2 robots", null);
        ReplayPage.fleet(data, world, List.of(
                new ReplayRobot(1, "MISSION_ACCOMPLISHED", "robot 1: done", world.robots().get(0), new ReplayData(Map.of())),
                new ReplayRobot(7, null, "robot 7", world.robots().get(1), new ReplayData(Map.of()))));
        String page = ReplayPage.html(data);
        assertThat(page).contains("<select id=\"robot\"></select>").contains("function drawOthers(")
                .contains("#robot=R&amp;iteration=N");
        JsonObject second = data.getAsJsonArray("robots").get(1).getAsJsonObject();
        assertThat(second.get("id").getAsInt()).isEqualTo(7);
        assertThat(second.get("robotRadiusM").getAsDouble()).isEqualTo(0.15);
        assertThat(second.getAsJsonArray("checkpoints")).hasSize(2);
        assertThat(data.getAsJsonObject("world").getAsJsonArray("stations")).hasSize(2);
    }
}
