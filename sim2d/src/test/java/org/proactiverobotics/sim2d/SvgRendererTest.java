package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;

class SvgRendererTest {

    private static Document parse(String svg) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(svg.getBytes(StandardCharsets.UTF_8)));
    }

    @Test
    void drawsTheWorld() throws Exception {
        WorldSpec w = WorldFiles.defaultWorld();
        Document doc = parse(new SvgRenderer(w).render());
        assertThat(doc.getDocumentElement().getTagName()).isEqualTo("svg");
        String svg = new SvgRenderer(w).render();
        assertThat(svg).contains("id=\"arena\"", "id=\"station\"", "recharge");
        assertThat(svg.split("<rect ", -1).length - 2).isEqualTo(2); // 2 boxes besides the background
        for (int i = 1; i <= w.checkpoints().size(); i++) {
            assertThat(svg).contains(">" + i + "</text>");
        }
        assertThat(svg).doesNotContain("id=\"robot\"", "id=\"trajectory\"");
    }

    @Test
    void drawsRobotRaysTrajectoryAndMarkers(@TempDir Path dir) throws Exception {
        WorldSpec w = WorldFiles.defaultWorld();
        Simulation sim = new Simulation(w);
        List<SvgRenderer.TrajectoryPoint> path = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            DeterminismTest.wander(sim.robot());
            sim.step();
            path.add(new SvgRenderer.TrajectoryPoint(sim.groundTruth().x(), sim.groundTruth().y(),
                    i < 100 ? "ReachDestination" : "ObstacleAvoidance"));
        }
        String svg = new SvgRenderer(w).robot(sim).trajectory(path).marker(-3, 0, "recharge 1")
                .colour("ReachDestination", "green").title("a <run>").render();
        parse(svg);
        assertThat(svg).contains("id=\"robot\"", "id=\"trajectory\"", "recharge 1", "a &lt;run&gt;",
                "stroke=\"green\"", "ObstacleAvoidance");
        assertThat(svg.split("<polyline", -1).length - 1).isEqualTo(2);
        assertThat(svg.split("<line ", -1).length - 1).isGreaterThanOrEqualTo(8 + 1 + 2);

        Path file = dir.resolve("w.svg");
        new SvgRenderer(w).robot(0, -4, Math.PI / 2).write(file);
        assertThat(Files.readString(file)).startsWith("<?xml").contains("id=\"robot\"");
    }
}
