package org.proactiverobotics.app.deploy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.Main;
import picocli.CommandLine;

class RobotIdsTest {

    @Test
    void idsAndRangesGiveEachRobotOnceInOrder() {
        assertThat(RobotIds.parse("1-3")).containsExactly(1, 2, 3);
        assertThat(RobotIds.parse("7, 1,3-4,3")).containsExactly(1, 3, 4, 7);
        assertThat(RobotIds.parse("0")).containsExactly(0);
        assertThat(RobotIds.parse("2147483647")).containsExactly(Integer.MAX_VALUE); // the loop ends at the last int
        assertThat(RobotIds.parse("1-10000,1-10000")).hasSize(10_000); // ids counted once
    }

    @Test
    void idsAreWrittenBackAsRanges() {
        assertThat(RobotIds.format(RobotIds.parse("7, 1,3-5,9,10"))).isEqualTo("1,3-5,7,9-10");
        assertThat(RobotIds.format(new int[0])).isEmpty();
    }

    @Test
    void whatIsNotAnIdOrARangeIsNamed() {
        assertThatThrownBy(() -> RobotIds.parse("1-x")).hasMessageContaining("'1-x'");
        assertThatThrownBy(() -> RobotIds.parse("5-2")).hasMessageContaining("'5-2'");
        assertThatThrownBy(() -> RobotIds.parse("1,,2")).hasMessageContaining("''");
        assertThatThrownBy(() -> RobotIds.parse("-3")).hasMessageContaining("'-3'");
        assertThatThrownBy(() -> RobotIds.parse("0-20000")).hasMessageContaining("more than 10000");
    }

    @Test
    void theEngineRefusesBadFleetOptionsWithExitTwoBeforeTouchingTheDatabase() {
        String[][] cases = {
                {"--robot-ids", "1-x"}, {"--robot-id", "2", "--robot-ids", "1-3"},
                {"--robot-ids", "1-3", "--standby-ids", "3-4"}, {"--lease-s", "0.1"}, {"--threads", "-1"},
                {"--threads", "2000000000"}, {"--engine-name", " "}};
        String[] expected = {"'1-x'", "not both", "robot 3 is in both", "--lease-s", "--threads", "--threads", "--engine-name"};
        for (int k = 0; k < cases.length; k++) {
            StringWriter err = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setErr(new PrintWriter(err, true));
            String[] args = new String[cases[k].length + 3];
            args[0] = "engine";
            args[1] = "--db";
            args[2] = "jdbc:mariadb://127.0.0.1:1/none"; // never reached: bad input is found first
            System.arraycopy(cases[k], 0, args, 3, cases[k].length);
            assertThat(cl.execute(args)).as(String.join(" ", args)).isEqualTo(2);
            assertThat(err.toString()).contains(expected[k]);
        }
    }
}
