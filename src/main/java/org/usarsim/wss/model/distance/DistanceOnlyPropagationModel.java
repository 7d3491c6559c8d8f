package org.usarsim.wss.model.distance;

import java.util.Map;
import org.usarsim.wss.model.simulator.PollClock;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.model.simulator.SimulatorModel;

/**
 * The original's DistanceOnly model: S = Pd0 - 10 N log10(d / d0) with d the 3-D distance between
 * two robots as the simulator reports it. A robot with no known position has NaN strength and may
 * connect (it is kicked at the next poll if the simulator does not list it); every registered
 * robot the simulator does not list is kicked.
 */
public final class DistanceOnlyPropagationModel extends SimulatorModel {

    public DistanceOnlyPropagationModel() {
    }

    /** A model whose poller takes its time from {@code clock}. */
    public DistanceOnlyPropagationModel(PollClock clock) {
        super(clock);
    }

    /** The path loss alone: obstacles are not counted. */
    @Override
    protected double strength(ReportedRobot a, ReportedRobot b, double obstacles) {
        return pathLoss().strength(a.distanceTo(b));
    }

    @Override
    protected boolean allowsUnknownRobots() {
        return true;
    }

    @Override
    protected boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed) {
        return true;
    }
}
