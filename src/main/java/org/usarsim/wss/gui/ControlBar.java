package org.usarsim.wss.gui;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.List;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * The top of the window: "Listen on port:", "Enable Logging", Start / Stop, "Propagation Model:"
 * and "Configure". Named port, eventLog, start, model, configure.
 */
final class ControlBar extends JPanel {

    /** Where the server is; what the bar lets the user do follows from it. */
    enum State { STOPPED, STARTING, RUNNING, STOPPING }

    final JTextField port = new JTextField(8);
    final JCheckBox eventLog = new JCheckBox("Enable Logging");
    final JButton start = new JButton("Start");
    final JComboBox<String> model;
    final JButton configure = new JButton("Configure");

    ControlBar(List<String> modelNames) {
        super(new GridBagLayout());
        model = new JComboBox<>(modelNames.toArray(String[]::new));
        port.setName("port");
        port.setToolTipText("The control port robots connect to (0: any free port); while the server runs, the port it listens on");
        port.setDisabledTextColor(DialogParts.READ_ONLY_TEXT); // locked while running, and still readable
        eventLog.setName("eventLog");
        eventLog.setToolTipText("Write every event to a CSV file (wss.eventLog)");
        start.setName("start");
        model.setName("model");
        configure.setName("configure");
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(3, 3, 3, 3);
        c.anchor = GridBagConstraints.WEST;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.gridx = 0;
        c.gridy = 0;
        add(new JLabel("Listen on port:"), c);
        c.gridx = 1;
        c.weightx = 1;
        add(port, c);
        c.weightx = 0;
        c.gridx = 2;
        add(eventLog, c);
        c.gridx = 3;
        add(start, c);
        c.gridx = 0;
        c.gridy = 1;
        add(new JLabel("Propagation Model:"), c);
        c.gridx = 1;
        c.gridwidth = 2;
        add(model, c);
        c.gridwidth = 1;
        c.gridx = 3;
        add(configure, c);
    }

    /** Event thread. Port, model and logging are locked unless stopped; Configure follows the model. */
    void show(State state, boolean configurable) {
        boolean stopped = state == State.STOPPED;
        port.setEnabled(stopped);
        model.setEnabled(stopped);
        eventLog.setEnabled(stopped);
        start.setText(switch (state) {
            case STOPPED -> "Start";
            case STARTING -> "Starting...";
            case RUNNING -> "Stop";
            case STOPPING -> "Stopping...";
        });
        start.setEnabled(stopped || state == State.RUNNING);
        configure.setEnabled(configurable);
    }
}
