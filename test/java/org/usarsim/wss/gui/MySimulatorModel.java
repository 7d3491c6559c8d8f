package org.usarsim.wss.gui;

import java.util.List;
import java.util.Map;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.model.simulator.SimulatorModel;

/** A plugin's simulator model: a {@link SimulatorModel} that is neither of the built-in ones, under a name of its own. */
final class MySimulatorModel extends SimulatorModel {

    private final String name;
    /** Its own declaration, or null for the simulator models'. */
    private final List<Setting> settings;

    MySimulatorModel() {
        this("MySimulatorModel");
    }

    MySimulatorModel(String name) {
        this(name, null);
    }

    MySimulatorModel(String name, List<Setting> settings) {
        this.name = name;
        this.settings = settings;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public List<Setting> settings() {
        return settings == null ? super.settings() : settings;
    }

    @Override
    protected double strength(ReportedRobot a, ReportedRobot b, double obstacles) {
        return 0;
    }

    @Override
    protected boolean allowsUnknownRobots() {
        return true;
    }

    @Override
    protected boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed) {
        return false;
    }
}
