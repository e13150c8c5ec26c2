package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.persistence.StateCodec;

/** The paper's CommandArray and PriorityArray, and their JSON round trip. */
class SharedMemoryTest {

    @Test
    void priorityArrayOrdersSlotsHighestFirstTiesBySlot() {
        SharedMemory memory = new SharedMemory(4);
        memory.priorityArray().set(0, 1);
        memory.priorityArray().set(1, 5);
        memory.priorityArray().set(2, 5);
        memory.priorityArray().set(3, 3);
        assertThat(memory.priorityArray().slotsByPriority()).containsExactly(1, 2, 3, 0);
    }

    @Test
    void commandArrayHoldsOneSuggestionPerSlot() {
        CommandArray commands = new SharedMemory(3).commandArray();
        commands.enter(2, "STOP", "ObstacleAvoidance", 7);
        assertThat(commands.get(2)).isEqualTo(new Suggestion("STOP", "ObstacleAvoidance", 7));
        assertThat(commands.get(0)).isNull();
        commands.clear(2);
        assertThat(commands.get(2)).isNull();
        assertThatThrownBy(() -> commands.enter(3, "X", "s", 1)).isInstanceOf(IndexOutOfBoundsException.class)
                .hasMessageContaining("slot 3 is outside 0..2");
    }

    @Test
    void memorySurvivesJson() {
        StateCodec codec = new StateCodec();
        SharedMemory memory = new SharedMemory(3);
        memory.commandArray().enter(1, "DRIVE 0.40 0.35", "ReachDestination", 12);
        memory.priorityArray().set(1, 9);
        memory.values().put("k", "v");
        SharedMemory back = codec.memory(codec.memoryJson(memory));
        assertThat(codec.memoryJson(back)).isEqualTo(codec.memoryJson(memory));
        assertThat(back.commandArray().get(1).command()).isEqualTo("DRIVE 0.40 0.35");
        assertThat(back.priorityArray().get(1)).isEqualTo(9);
        assertThatThrownBy(() -> codec.memory("{\"commandArray\":{\"slots\":[null]},\"priorityArray\":{\"priorities\":[1,2]},\"values\":{}}"))
                .hasMessageContaining("CommandArray has 1 slots but PriorityArray 2");
    }
}
