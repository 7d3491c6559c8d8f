package org.usarsim.wss.replay;

import java.util.Map;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.RobotPair;

/**
 * The poll a replay applied last, swapped whole by its player: its index in the recording, its
 * robots by name, its pairs. GETSS, DNS, accepts and the map read it.
 */
record AppliedPoll(int index, Map<String, ModelPoll.Robot> robots, Map<RobotPair, ModelPoll.Pair> pairs) {

    /** Before the first poll of a run. */
    static final AppliedPoll NONE = new AppliedPoll(-1, Map.of(), Map.of());
}
