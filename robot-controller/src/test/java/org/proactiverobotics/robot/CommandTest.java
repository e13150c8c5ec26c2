package org.proactiverobotics.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class CommandTest {

    private static final double MAX = 0.5;

    @Test
    void parsesEveryCommandMode() throws Exception {
        assertThat(Command.parse("STOP", MAX)).isEqualTo(Command.STOP);
        assertThat(Command.parse("  DRIVE 0.40   -0.35 ", MAX)).isEqualTo(new Command(Mode.DRIVE, 0.40, -0.35));
        assertThat(Command.parse("FORWARD .25", MAX)).isEqualTo(new Command(Mode.FORWARD, 0.25, 0.25));
        assertThat(Command.parse("TURN_LEFT 0.2", MAX)).isEqualTo(new Command(Mode.TURN_LEFT, -0.2, 0.2));
        assertThat(Command.parse("TURN_RIGHT 2e-1", MAX)).isEqualTo(new Command(Mode.TURN_RIGHT, 0.2, -0.2));
        assertThat(Command.parse("RECHARGE", MAX).mode()).isEqualTo(Mode.RECHARGE);
        assertThat(Command.parse("DRIVE 0.5 -0.5", MAX)).isEqualTo(new Command(Mode.DRIVE, 0.5, -0.5));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "   ", "JUMP", "stop", "WAITING", "STOP 1", "DRIVE 0.1", "DRIVE 0.1 0.1 0.1",
        "DRIVE NaN 0", "DRIVE Infinity 0", "DRIVE 0x1p-2 0", "DRIVE 0.1d 0", "DRIVE 0.6 0", "DRIVE 0 -0.51",
        "FORWARD", "TURN_LEFT -0.1", "TURN_RIGHT 1e3", "FORWARD 1e400", "DRIVE 0,1 0", "RECHARGE now"})
    void refusesMalformedCommands(String text) {
        assertThatThrownBy(() -> Command.parse(text, MAX)).isInstanceOf(MalformedCommandException.class);
    }

    @Test
    void refusesNull() {
        assertThatThrownBy(() -> Command.parse(null, MAX)).isInstanceOf(MalformedCommandException.class);
    }

    @Test
    void everyCommandModeHasAnArity() {
        for (Mode m : Mode.values()) {
            assertThat(m.isCommand()).isEqualTo(m != Mode.WAITING);
            assertThat(Mode.command(m.name()).isPresent()).isEqualTo(m.isCommand());
        }
    }
}
