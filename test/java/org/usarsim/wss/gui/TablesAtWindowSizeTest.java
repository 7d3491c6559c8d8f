package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.Component;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.table.TableColumn;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/**
 * Issue 26, item 1, read off the window at the size it opens (960 x 700) under a display: every
 * column header of the Link statistics and of the Connections tables shows whole (its text, by
 * the header renderer's font metrics, no wider than its column), robot names of 12 characters
 * show whole, and byte counts are grouped.
 */
@Tag("slow")
@Timeout(60)
class TablesAtWindowSizeTest {

    private static final String ALPHA = "Explorer1234";
    private static final String BRAVO = "Operator5678";

    private OpenWindow window;
    private HubServers servers;
    private WindowLog windowLog;
    private JFrame frame;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @BeforeEach
    void open() throws Exception {
        window = new OpenWindow(TestHub.config(true, 65536, 600, 1000, 30), List.of(ModelProvider.of(NoopPropagationModel::new)),
                "NoopPropagationModel");
        servers = window.servers;
        windowLog = window.windowLog;
        frame = window.frame;
    }

    @AfterEach
    void close() throws Exception {
        window.close();
    }

    @Test
    void everyHeaderAndEveryNameOfTwelveCharactersShowsWholeAtTheWindowsOwnSize() throws Exception {
        assertEquals(List.of(960, 700), onEdt(() -> List.of(frame.getWidth(), frame.getHeight())), "the size it opens at");
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        int port = servers.running().port();
        try (TestRobot alpha = new TestRobot(port, "127.0.0.2"); TestRobot bravo = new TestRobot(port, "127.0.0.3")) {
            alpha.initAccepting(ALPHA);
            ServerSocket bravoAccepts = bravo.initAccepting(BRAVO);
            alpha.dns(BRAVO, 0);
            JTable ports = table("ports");
            until("the port shows", () -> cells(ports).size() == 1);
            for (String name : List.of("robots", "ports", "links")) {
                JTable table = table(name);
                assertWhole(table);
                // The Connections tab's tables fit at 960 x 700: no column a sideways scroll away.
                assertTrue(onEdt(() -> minimum(table) <= table.getParent().getWidth()),
                        name + " fits its viewport: " + onEdt(() -> widths(table)));
            }
            JTabbedPane tabs = onEdt(() -> find(frame.getContentPane(), JTabbedPane.class, "tabs"));
            run(() -> tabs.setSelectedIndex(tabs.indexOfTab("Link statistics")));
            JTable shown = table("stats");
            until("the statistics show the pair", () -> shown.isShowing() && cells(shown).size() == 1);
            assertWhole(shown);
            // Sixteen columns whole are wider than 960: the table scrolls sideways rather than cut one.
            assertTrue(onEdt(() -> shown.getWidth() >= minimum(shown)),
                    "no column squeezed below its least width: " + onEdt(() -> widths(shown)));
            javax.swing.JScrollPane scroll = onEdt(() -> (javax.swing.JScrollPane) javax.swing.SwingUtilities
                    .getAncestorOfClass(javax.swing.JScrollPane.class, shown));
            assertTrue(onEdt(() -> scroll.getHorizontalScrollBar().isShowing()), "the sideways scroll bar shows");
            assertEquals(List.of(ALPHA, BRAVO), onEdt(() -> cells(shown).get(0).subList(0, 2)));
            bravoAccepts.close();
        }
        JTable stats = table("stats");
        assertEquals("6,116,163,584", onEdt(() -> text(stats, 6_116_163_584L)), "byte counts grouped");
    }

    /** The viewport's width, then each column's least width. */
    private static String widths(JTable table) {
        StringBuilder text = new StringBuilder(table.getParent().getWidth() + ":");
        for (int column = 0; column < table.getColumnCount(); column++) {
            text.append(' ').append(table.getColumnModel().getColumn(column).getMinWidth());
        }
        return text.toString();
    }

    private static int minimum(JTable table) {
        int sum = 0;
        for (int column = 0; column < table.getColumnCount(); column++) {
            sum += table.getColumnModel().getColumn(column).getMinWidth();
        }
        return sum;
    }

    private JTable table(String name) {
        return onEdt(() -> find(frame.getContentPane(), JTable.class, name));
    }

    /** Every header's text and every name cell of the table no wider than its column. Event thread via onEdt. */
    private void assertWhole(JTable table) {
        List<String> cut = onEdt(() -> {
            List<String> problems = new ArrayList<>();
            for (int column = 0; column < table.getColumnCount(); column++) {
                TableColumn shown = table.getColumnModel().getColumn(column);
                Component header = table.getTableHeader().getDefaultRenderer()
                        .getTableCellRendererComponent(table, shown.getHeaderValue(), false, false, -1, column);
                if (header.getPreferredSize().height > table.getTableHeader().getHeight()) {
                    problems.add(table.getName() + " header " + shown.getHeaderValue() + ": " + header.getPreferredSize().height
                            + " px high in " + table.getTableHeader().getHeight());
                }
                if (header.getPreferredSize().width > shown.getWidth()) {
                    problems.add(table.getName() + " header " + shown.getHeaderValue() + ": " + header.getPreferredSize().width
                            + " px in " + shown.getWidth());
                }
                for (int row = 0; row < table.getRowCount(); row++) {
                    Object value = table.getValueAt(row, column);
                    if (value instanceof String text && (text.equals(ALPHA) || text.equals(BRAVO))) {
                        Component cell = table.getCellRenderer(row, column).getTableCellRendererComponent(table, value, false, false,
                                row, column);
                        if (cell.getPreferredSize().width > shown.getWidth()) {
                            problems.add(table.getName() + " cell " + text + ": " + cell.getPreferredSize().width + " px in "
                                    + shown.getWidth());
                        }
                    }
                }
            }
            return problems;
        });
        assertEquals(List.of(), cut, "cut at 960 x 700");
    }

    /** What the table's renderer for counts shows for {@code count}. */
    private static String text(JTable table, long count) {
        return ((javax.swing.JLabel) table.getDefaultRenderer(Long.class).getTableCellRendererComponent(table, count, false, false, 0, 5))
                .getText();
    }
}
