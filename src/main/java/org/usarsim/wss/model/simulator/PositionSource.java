package org.usarsim.wss.model.simulator;

import java.io.Closeable;
import java.io.IOException;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;

/**
 * Where the robots are now (and what walls there are), as a simulator model polls it: a USARSim
 * position socket ({@link UsarsimSource}), a rosbridge WebSocket ({@link RosbridgeSource}), or any
 * other, one class each. A run opens one with its {@link Opener}, asks it at every poll, closes it
 * when it is lost and opens another with a growing pause. The models' rules (kicks, silence,
 * hysteresis, recording) are the model's: a source only says where the robots are, or that it is
 * silent, by throwing. Used by one thread at a time, the model's poller.
 */
public interface PositionSource extends Closeable {

    /**
     * The robots the source lists now, by their WSS names; a robot it does not list (any longer) is
     * absent. Null while a source just opened knows nothing yet (no message came on a new
     * WebSocket): the poll acts on nothing then, rather than kick every robot. {@code registered}
     * are the robots registered with the WSS, for a source that must ask for each robot by name.
     *
     * @throws IOException when the source is silent or unusable (gone, unreachable, late, garbage):
     *                     the model keeps the last state, says so once and opens the source again
     */
    Map<String, ReportedRobot> positions(List<String> registered) throws IOException;

    /**
     * The registered robots the last {@link #positions} could not tell about yet, though it lists
     * others: a robot whose first pose may still come (rosbridge subscribes to a robot's own topic
     * only as it registers, and a robot's publisher may start after its INIT). The model neither
     * kicks them nor decides their pairs until the source lists them, or stops waiting for them.
     * None by default.
     */
    default Set<String> waitedFor() {
        return Set.of();
    }

    /**
     * The walls the source gave, for the map and the recording: null while it is not known yet
     * whether it gives any; empty when it gives none.
     */
    List<Wall> walls();

    /** Why the walls the source sent were not used (they could not be read); null when they were, or none came. */
    String wallsProblem();

    /**
     * The obstacle count between each of these pairs of robots the source can count (a pair it
     * cannot count is absent): all of them, some or none. NaN where it answered that it does not know.
     */
    Map<RobotPair, Double> obstacles(Collection<RobotPair> pairs) throws IOException;

    /** Closes it; a poll under way fails. Never throws. */
    @Override
    void close();

    /** How a run opens its source: at its start, and again each time the source was lost. */
    interface Opener {

        /** A new source, connected. */
        PositionSource open() throws IOException;

        /** Where the source is, as the log says it: {@code host:port}, or the URL and topic. */
        String where();

        /**
         * Whether a run starts when the source cannot be reached at its start: then it is silent
         * from the start and opened again as a lost one is. Else the start is refused.
         */
        boolean startsSilent();
    }
}
