package org.proactiverobotics.sim2d;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

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
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

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

    @Test
    void marksTheStartPoseAndDrawsAOneMetreScaleBar() throws Exception {
        WorldSpec w = WorldFiles.defaultWorld();
        Document doc = parse(new SvgRenderer(w).render());
        Element start = group(doc, "start");
        Element disc = (Element) start.getElementsByTagName("circle").item(0);
        assertThat(Double.parseDouble(disc.getAttribute("cx"))).isEqualTo(w.robot().x());
        assertThat(Double.parseDouble(disc.getAttribute("cy"))).isEqualTo(-w.robot().y());
        assertThat(start.getTextContent()).isEqualTo("start");

        Element scale = group(doc, "scale");
        Element bar = (Element) scale.getElementsByTagName("line").item(0);
        assertThat(Double.parseDouble(bar.getAttribute("x2")) - Double.parseDouble(bar.getAttribute("x1")))
                .isCloseTo(1.0, within(1e-9));
        assertThat(bar.getAttribute("y1")).isEqualTo(bar.getAttribute("y2"));
        assertThat(scale.getTextContent()).isEqualTo("1 m");
    }

    @Test
    void checkpointNumbersAreDrawnAboveTheRobotOnTopOfIt() throws Exception {
        WorldSpec w = WorldFiles.defaultWorld();
        WorldSpec.Checkpoint last = w.checkpoints().get(w.checkpoints().size() - 1);
        // the robot as a mission leaves it: on the last checkpoint
        String svg = new SvgRenderer(w).robot(last.x(), last.y(), Math.PI / 2).render();
        assertThat(svg.indexOf("id=\"checkpoint-labels\"")).isGreaterThan(svg.indexOf("id=\"robot\""));
        NodeList labels = group(parse(svg), "checkpoint-labels").getElementsByTagName("text");
        assertThat(labels.getLength()).isEqualTo(w.checkpoints().size());
        for (int i = 0; i < labels.getLength(); i++) {
            Element label = (Element) labels.item(i);
            WorldSpec.Checkpoint c = w.checkpoints().get(i);
            assertThat(label.getTextContent()).isEqualTo(String.valueOf(i + 1));
            assertThat(Double.parseDouble(label.getAttribute("x"))).isEqualTo(c.x());
            // the baseline (SVG y grows downwards) is above a robot anywhere inside the checkpoint
            assertThat(Double.parseDouble(label.getAttribute("y")))
                    .isLessThan(-c.y() - w.checkpointRadiusM() - w.robot().radiusM());
        }
    }

    @Test
    void everyCategoryHasAColourOfItsOwn() {
        WorldSpec w = WorldFiles.defaultWorld();
        SvgRenderer renderer = new SvgRenderer(w).colour("DecisionMaking", "#7f7f7f");
        assertThatThrownBy(() -> renderer.colour("none", "#7F7F7F")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("DecisionMaking");
        // a category without a fixed colour takes a palette colour nobody has
        String svg = new SvgRenderer(w).colour("A", "#1f77b4").colour("B", "#d62728")
                .trajectory(List.of(new SvgRenderer.TrajectoryPoint(0, 0, "A"), new SvgRenderer.TrajectoryPoint(1, 0, "B"),
                        new SvgRenderer.TrajectoryPoint(1, 1, "C")))
                .render();
        assertThat(svg).contains("<polyline stroke=\"#2ca02c\"");
    }

    private static Element group(Document doc, String id) {
        NodeList groups = doc.getElementsByTagName("g");
        for (int i = 0; i < groups.getLength(); i++) {
            Element g = (Element) groups.item(i);
            if (id.equals(g.getAttribute("id"))) {
                return g;
            }
        }
        throw new AssertionError("no <g id=\"" + id + "\">");
    }
}
