package org.usarsim.wss.gui;

import java.awt.Component;
import javax.swing.JOptionPane;
import org.usarsim.wss.Version;

/** The Help menu's About dialog: what this is, its version, its licence and the manual it reimplements. */
final class AboutDialog {

    static final String TITLE = "About WSS";

    private AboutDialog() {
    }

    /** The dialog's text, one paragraph a line. */
    static String text() {
        return "<html><body style='width: 360px'>"
                + "<p><b>WSS - Wireless Simulation Server</b></p>"
                + "<p>Version " + Version.current() + "</p><br>"
                + "<p>A Java reimplementation of the RoboCup Rescue Virtual Robots Wireless Simulation Server, "
                + "as its manual describes it: <i>RoboCup Rescue Virtual Robots: Wireless Simulation Server "
                + "Documentation</i>, Max Pfingsthorn, October 8, 2008.</p><br>"
                + "<p>Licence: GNU General Public License, version 2, as the original.</p>"
                + "</body></html>";
    }

    /** Shows it, modal, over {@code owner}. Event thread. */
    static void show(Component owner) {
        JOptionPane.showMessageDialog(owner, text(), TITLE, JOptionPane.INFORMATION_MESSAGE, Icons.of(48));
    }
}
