package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.all;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.Component;
import java.awt.Rectangle;
import java.awt.Window;
import java.awt.event.MouseEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JScrollPane;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import javax.swing.table.TableColumn;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.HubSnapshot.PairEntry;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.hub.core.UdpCounts;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * Issue 36, items 6 and 7b, read off the real window under a display: a robot's many ports, the
 * UDP counts of a busy pair and the Airtime header at 800 x 600 are never cut (their column as wide
 * as they are, the table scrolling sideways), a name cut all the same has its whole text as
 * tooltip, and an error dialog's long message is wrapped to a readable width.
 */
@Tag("slow")
@Timeout(60)
class CutTextWindowTest {

    private static final String LONG_NAME = "ExplorerWithAVeryLongName";
    /** A reason as long as the one of a recording without polls. */
    private static final String LONG_REASON = "the recording /home/operator/runs/run-2026.11.28-06.55.54.123.rec has no poll:"
            + " a replay needs at least one poll of the model's positions to place the robots, and this file holds only"
            + " its header and its end (14 end); record a run in which the model polled at least once, or choose another"
            + " file as replay.file in the model's settings";

    private OpenWindow window;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            window.close();
        }
    }

    private JFrame open(List<ModelProvider> models) throws Exception {
        window = new OpenWindow(TestHub.config(true, 65536, 600, 1000, 30), models, "NoopPropagationModel");
        return window.frame;
    }

    private JTable table(String name) {
        return onEdt(() -> find(window.frame.getContentPane(), JTable.class, name));
    }

    @Test
    void manyPortsShowWholeTheAirtimeHeaderTooAt800x600AndACutNameHasItsTooltip() throws Exception {
        JFrame frame = open(List.of(ModelProvider.of(NoopPropagationModel::new)));
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        int port = window.servers.running().port();
        int[] many = new int[10];
        for (int i = 0; i < many.length; i++) {
            many[i] = 45807 + i;
        }
        try (TestRobot alpha = new TestRobot(port, "127.0.0.2"); TestRobot bravo = new TestRobot(port, "127.0.0.3")) {
            alpha.init("Explorer1234", many);
            bravo.init(LONG_NAME, 45900);
            JTable robots = table("robots");
            until("both robots show", () -> cells(robots).size() == 2);
            for (List<Integer> size : List.of(List.of(960, 700), List.of(800, 600))) {
                run(() -> {
                    frame.setSize(size.get(0), size.get(1));
                    frame.validate();
                });
                String at = size.get(0) + " x " + size.get(1);
                assertEquals(List.of(), onEdt(() -> cut(robots, 2)), "the ports whole at " + at);
                assertEquals(List.of(), onEdt(() -> cutHeaders(robots)), "the headers whole at " + at);
                assertEquals(List.of(), onEdt(() -> beyondTheTable(robots)), "no column beyond the table at " + at);
                JScrollPane scroll = onEdt(() -> (JScrollPane) SwingUtilities.getAncestorOfClass(JScrollPane.class, robots));
                assertTrue(onEdt(() -> robots.getWidth() <= scroll.getViewport().getWidth()
                        || scroll.getHorizontalScrollBar().isShowing()), "what the view does not hold scrolls sideways at " + at);
            }
            // A name longer than the 12 characters the Name column is sized for: its tooltip is the name.
            int row = onEdt(() -> cells(robots).stream().map(cells -> cells.get(0)).toList().indexOf(LONG_NAME));
            assertEquals(LONG_NAME, onEdt(() -> tooltip(robots, row, 0)), "the cut name's tooltip");
        }
    }

    @Test
    void theUdpCountsOfABusyPairShowWhole() throws Exception {
        JFrame frame = open(List.of(ModelProvider.of(NoopPropagationModel::new)));
        JTabbedPane tabs = onEdt(() -> find(frame.getContentPane(), JTabbedPane.class, "tabs"));
        run(() -> tabs.setSelectedIndex(tabs.indexOfTab("Link statistics")));
        StatsPanel stats = onEdt(() -> all(frame.getContentPane(), StatsPanel.class).get(0));
        // The window's own panel given what a snapshot of a busy pair holds (no server runs: nothing else fills it).
        PairEntry busy = new PairEntry("Base", "Scout", PairState.UP, -60, 5, 0, 0, 0, 0, 0, 0, 0, 1, null, 0, 0,
                new UdpCounts.Reading(2_318_235, 2_318_235_000L, 1_204, 35_112, 98_765),
                new UdpCounts.Reading(1_159_023, 1_159_023_000L, 0, 12, 4_321));
        run(() -> stats.show(List.of(busy)));
        JTable table = table("stats");
        until("the pair shows", () -> table.isShowing() && cells(table).size() == 1);
        assertEquals("2318235/1204/35112/98765 | 1159023/0/12/4321", onEdt(() -> cells(table).get(0).get(15)));
        assertEquals(List.of(), onEdt(() -> cut(table, 15)), "the UDP counts whole");
        assertTrue(onEdt(() -> table.getWidth() >= leastWidth(table)), "no column squeezed below its least width");
    }

    @Test
    void aLongErrorIsWrappedToAReadableWidth() throws Exception {
        AtomicInteger made = new AtomicInteger();
        // The catalog's instance, then a run's that cannot be made: the window's Start fails with a long reason.
        JFrame frame = open(List.of(ModelProvider.of(() -> {
            if (made.getAndIncrement() > 0) {
                throw new IllegalStateException(LONG_REASON);
            }
            return new NoopPropagationModel();
        })));
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the error shows", () -> Gui.showing("WSS").size() == 1);
        Window dialog = onEdt(() -> Gui.showing("WSS").get(0));
        int width = onEdt(dialog::getWidth);
        assertTrue(width <= 700, "the dialog is " + width + " px wide");
        JTextArea text = onEdt(() -> all(dialog, JTextArea.class).get(0));
        String shown = onEdt(text::getText);
        assertTrue(shown.contains(LONG_REASON), shown);
        assertTrue(onEdt(() -> text.getLineWrap() && text.getWrapStyleWord()), "wrapped at words");
        // Every line of it shown: the area as tall as its wrapped text needs.
        assertTrue(onEdt(() -> text.getHeight() >= text.getPreferredSize().height && text.getHeight() > 3 * text.getFont().getSize()),
                (String) onEdt(() -> text.getSize() + " for " + text.getPreferredSize()));
        assertTrue(Gui.closeMessage("WSS").contains(LONG_REASON));
    }

    /** The cells of a column whose text the column cuts. Event thread. */
    private static List<String> cut(JTable table, int column) {
        List<String> problems = new ArrayList<>();
        for (int row = 0; row < table.getRowCount(); row++) {
            Component cell = table.prepareRenderer(table.getCellRenderer(row, column), row, column);
            Rectangle shown = table.getCellRect(row, column, false);
            if (cell.getPreferredSize().width > shown.width) {
                problems.add(((JLabel) cell).getText() + ": " + cell.getPreferredSize().width + " px in " + shown.width);
            }
        }
        return problems;
    }

    /** The headers their column cuts. Event thread. */
    private static List<String> cutHeaders(JTable table) {
        List<String> problems = new ArrayList<>();
        for (int column = 0; column < table.getColumnCount(); column++) {
            TableColumn shown = table.getColumnModel().getColumn(column);
            Component header = table.getTableHeader().getDefaultRenderer()
                    .getTableCellRendererComponent(table, shown.getHeaderValue(), false, false, -1, column);
            if (header.getPreferredSize().width > shown.getWidth()) {
                problems.add(shown.getHeaderValue() + ": " + header.getPreferredSize().width + " px in " + shown.getWidth());
            }
        }
        return problems;
    }

    /** The columns that end beyond the table's own width (drawn cut, with no scroll to them). Event thread. */
    private static List<String> beyondTheTable(JTable table) {
        List<String> problems = new ArrayList<>();
        int right = 0;
        for (int column = 0; column < table.getColumnCount(); column++) {
            right += table.getColumnModel().getColumn(column).getWidth();
            if (right > table.getWidth()) {
                problems.add(table.getColumnName(column) + " ends at " + right + " in " + table.getWidth());
            }
        }
        return problems;
    }

    private static int leastWidth(JTable table) {
        int sum = 0;
        for (int column = 0; column < table.getColumnCount(); column++) {
            sum += table.getColumnModel().getColumn(column).getMinWidth();
        }
        return sum;
    }

    /** The tooltip the table gives at the middle of a cell. Event thread. */
    private static String tooltip(JTable table, int row, int column) {
        Rectangle cell = table.getCellRect(row, column, false);
        return table.getToolTipText(new MouseEvent(table, MouseEvent.MOUSE_MOVED, 0, 0, (int) cell.getCenterX(), (int) cell.getCenterY(),
                0, false));
    }
}
