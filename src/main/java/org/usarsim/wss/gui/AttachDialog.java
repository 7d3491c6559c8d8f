package org.usarsim.wss.gui;

import java.awt.Window;
import java.util.List;
import javax.swing.JCheckBox;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JPasswordField;
import javax.swing.JTextField;

/**
 * File > Attach... (docs/gui.md): the monitor's URL, its token (hidden as typed) and, for https
 * with a certificate of its own, the certificate file to trust; "Remember the token on this
 * computer" keeps it in java.util.prefs, unticked it lives only in memory for this attach. Modal;
 * event thread. It connects to nothing: {@link Attaching} does, with {@link #asked()}.
 */
final class AttachDialog extends JDialog {

    /** Component names, for tests; the message and the buttons are named as in {@link DialogParts}. */
    static final String URL = "attachUrl";
    static final String TOKEN = "attachToken";
    static final String CERT = "attachCert";
    static final String REMEMBER = "attachRemember";

    private final JLabel message = new JLabel(" ");
    private final JTextField url = new JTextField(28);
    private final JPasswordField token = new JPasswordField(28);
    private final JTextField cert = new JTextField(28);
    private final JCheckBox remember = new JCheckBox("Remember the token on this computer");
    private Attaching.Request asked;

    AttachDialog(Window owner, String urlShown, String certShown) {
        super(owner, "Attach to a WSS", ModalityType.APPLICATION_MODAL);
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        JPanel fields = DialogParts.titled("A WSS's monitor endpoint (docs/monitor.md)");
        field(fields, 0, "URL", url, URL, "https://host:port or http://127.0.0.1:port (through an SSH tunnel)");
        field(fields, 1, "Token", token, TOKEN, "A viewer's or an operator's token of the server's wss.monitor.tokens file");
        field(fields, 2, "Certificate", cert, CERT,
                "https only: a PEM file (keytool -exportcert -rfc) to trust alone; empty: the JDK's trust store");
        url.setText(urlShown);
        cert.setText(certShown);
        DialogParts.checkBox(remember, REMEMBER, "Unticked, the token is kept in memory for this attach only", false, true);
        fields.add(remember, DialogParts.cell(1, 3, 8, true));
        DialogParts.layOut(this, owner, List.of(fields), message, DialogParts.buttons(this, true, this::ok));
    }

    /** Shows the dialog and waits for it: what OK accepted, or null. Event thread. */
    static Attaching.Request ask(Window owner, String urlShown, String certShown) {
        AttachDialog dialog = new AttachDialog(owner, urlShown, certShown);
        dialog.setVisible(true);
        return dialog.asked();
    }

    Attaching.Request asked() {
        return asked;
    }

    private static void field(JPanel panel, int y, String label, JTextField field, String name, String help) {
        field.setName(name);
        field.setToolTipText(help);
        DialogParts.row(panel, y, DialogParts.label(label, help, field), field, new JLabel());
    }

    private void ok() {
        String typed = url.getText().strip();
        String secret = new String(token.getPassword()).strip();
        String problem = !Attaching.isMonitorUrl(typed) ? "URL: https://host:port or http://host:port"
                : secret.isEmpty() ? "Token: the server's viewer or operator token" : null;
        if (problem != null) {
            DialogParts.showMessage(message, problem);
            return;
        }
        asked = new Attaching.Request(typed, secret, cert.getText().strip(), remember.isSelected());
        dispose();
    }
}
