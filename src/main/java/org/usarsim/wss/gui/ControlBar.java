package org.usarsim.wss.gui;

import java.awt.FlowLayout;
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
import org.usarsim.wss.shaping.Bitrate;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The top of the window: "Listen on port:", "Enable Logging" and "Record", Start / Stop, "Propagation Model:"
 * and "Configure", then what the link shaping of the next Start (or of the server that runs) is,
 * and "Link shaping...". Named port, eventLog, record, start, model, configure, shapingSummary, shaping.
 */
final class ControlBar extends JPanel {

    /** Where the server is; what the bar lets the user do follows from it. */
    enum State { STOPPED, STARTING, RUNNING, STOPPING }

    final JTextField port = new JTextField(8);
    final JCheckBox eventLog = new JCheckBox("Enable Logging");
    final JCheckBox record = new JCheckBox("Record");
    final JButton start = new JButton("Start");
    final JComboBox<String> model;
    final JButton configure = new JButton("Configure");
    final JLabel shapingSummary = new JLabel();
    final JButton shaping = new JButton("Link shaping...");

    ControlBar(List<String> modelNames) {
        super(new GridBagLayout());
        model = new JComboBox<>(modelNames.toArray(String[]::new));
        port.setName("port");
        port.setToolTipText("The control port robots connect to (0: any free port); while the server runs, the port it listens on");
        port.setDisabledTextColor(DialogParts.READ_ONLY_TEXT); // locked while running, and still readable
        eventLog.setName("eventLog");
        eventLog.setToolTipText("Write every event to a CSV file (wss.eventLog)");
        record.setName("record");
        record.setToolTipText("Record the run (positions, strengths, breaks, resumes) to run-<time>.rec in the event log's folder,"
                + " or to the --config file's wss.record, to replay it later (docs/replay.md)");
        start.setName("start");
        model.setName("model");
        configure.setName("configure");
        shapingSummary.setName("shapingSummary");
        shaping.setName("shaping");
        shaping.setToolTipText("Shape links like radio: rate and delay from the signal strength, shared airtime (docs/shaping.md)");
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
        JPanel boxes = new JPanel(new FlowLayout(FlowLayout.LEFT, 0, 0));
        boxes.add(eventLog);
        boxes.add(record);
        add(boxes, c);
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
        c.gridx = 0;
        c.gridy = 2;
        c.gridwidth = 3;
        add(shapingSummary, c);
        c.gridwidth = 1;
        c.gridx = 3;
        add(shaping, c);
    }

    /** Event thread. Says what link shaping the next Start uses (or the server that runs), in one line; the table in the tooltip. */
    void showShaping(ShapingConfig config) {
        if (!config.on()) {
            shapingSummary.setText("Links not shaped");
        } else {
            String lowest = Bitrate.format(config.rates().lowestRate());
            String top = Bitrate.format(config.rates().topRate());
            String unit = top.substring(top.indexOf(' ')); // " Mbit/s": said once when both have it, "6 to 54 Mbit/s"
            String rates = lowest.equals(top) ? top : (lowest.endsWith(unit) ? lowest.substring(0, lowest.indexOf(' ')) : lowest) + " to " + top;
            String jitter = config.jitter().ms() > 0 ? " (jitter " + config.jitter().ms() + " ms " + config.jitter().distribution().word() + ")" : "";
            shapingSummary.setText("Links shaped: " + rates + " by strength, " + config.delayMs() + " ms delay" + jitter + ", "
                    + (config.airtime() ? "shared airtime" : "airtime not shared"));
        }
        shapingSummary.setToolTipText("Rates by strength (dBm:rate): " + config.rates());
    }

    /** Event thread. Port, model, logging and recording are locked unless stopped; Configure follows the model. */
    void show(State state, boolean configurable) {
        boolean stopped = state == State.STOPPED;
        port.setEnabled(stopped);
        model.setEnabled(stopped);
        eventLog.setEnabled(stopped);
        record.setEnabled(stopped);
        start.setText(switch (state) {
            case STOPPED -> "Start";
            case STARTING -> "Starting...";
            case RUNNING -> "Stop";
            case STOPPING -> "Stopping...";
        });
        start.setEnabled(stopped || state == State.RUNNING);
        configure.setEnabled(configurable);
    }

    /** Event thread. An attached window: the server's own port, model, logging, Start / Stop and dialogs, shown read-only. */
    void serversOwn(String title) {
        String tip = "The server's own: the window " + title.substring(title.indexOf(" - ") + 3) + " shows it and cannot change it";
        for (javax.swing.JComponent part : List.of(port, eventLog, record, start, model, configure, shaping)) {
            part.setEnabled(false);
            part.setToolTipText(tip);
        }
        start.setText("Stop");
        shapingSummary.setText("Link shaping: the server's");
    }

    /** Event thread. An attached window: the server's model and control port (0: not known). */
    void showServer(String modelName, int controlPort) {
        port.setText(controlPort > 0 ? String.valueOf(controlPort) : "");
        if (model.getItemCount() != 1 || !modelName.equals(model.getItemAt(0))) {
            model.removeAllItems();
            model.addItem(modelName);
        }
    }
}
