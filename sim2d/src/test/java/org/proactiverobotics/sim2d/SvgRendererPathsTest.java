package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** Each trajectory() call is a path of its own: two robots' paths are never joined by a line. */
class SvgRendererPathsTest {

    private static List<String> polylines(String svg) {
        Matcher m = Pattern.compile("<polyline stroke=\"[^\"]*\" points=\"([^\"]*)\"").matcher(svg);
        List<String> out = new java.util.ArrayList<>();
        while (m.find()) {
            out.add(m.group(1).trim());
        }
        return out;
    }

    @Test
    void twoCallsDrawTwoPathsThatDoNotMeet() {
        String svg = new SvgRenderer(Worlds.empty(3.0, 0.0, 0.0, 0.0))
                .trajectory(List.of(new SvgRenderer.TrajectoryPoint(0, 0, "robot 1"), new SvgRenderer.TrajectoryPoint(1, 0, "robot 1")))
                .trajectory(List.of(new SvgRenderer.TrajectoryPoint(0, 2, "robot 2"), new SvgRenderer.TrajectoryPoint(0, 1, "robot 2")))
                .render();
        assertThat(polylines(svg)).containsExactly("0.000,0.000 1.000,0.000", "0.000,-2.000 0.000,-1.000");
    }

    @Test
    void oneCallStillJoinsItsRunsOfCategories() {
        String svg = new SvgRenderer(Worlds.empty(3.0, 0.0, 0.0, 0.0))
                .trajectory(List.of(new SvgRenderer.TrajectoryPoint(0, 0, "a"), new SvgRenderer.TrajectoryPoint(1, 0, "a"),
                        new SvgRenderer.TrajectoryPoint(2, 0, "b")))
                .render();
        assertThat(polylines(svg)).containsExactly("0.000,0.000 1.000,0.000", "1.000,0.000 2.000,0.000");
    }
}
