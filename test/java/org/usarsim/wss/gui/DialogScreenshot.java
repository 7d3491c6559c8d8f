package org.usarsim.wss.gui;

import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.File;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.prefs.Preferences;
import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.distance.SimulatorModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;

/**
 * Takes a picture of the model dialog as a user sees it, for docs/images. Run under a display,
 * with a window manager for the title bar (a bare Xvfb has none; docs/images' picture was taken
 * with openbox, {@code apt-get install openbox}):
 *
 * <pre>
 * mvn -B -q test-compile
 * xvfb-run -a sh -c 'openbox &amp; sleep 1; java -cp target/classes:target/test-classes \
 *     org.usarsim.wss.gui.DialogScreenshot docs/images/distanceonly-dialog.png \
 *     DistanceOnlyPropagationModel|ObstaclePropagationModel [readonly] [key=value ...] [ok]'
 * </pre>
 *
 * <p>A {@code key=value} argument types the value into the field of that name before the picture
 * ({@code cutoffDistance=55.6}); {@code ok} presses OK first (to show a refusal). The settings
 * come from a throw-away preferences node, removed afterwards.
 */
public final class DialogScreenshot {

    private DialogScreenshot() {
    }

    public static void main(String[] args) throws Exception {
        File out = new File(args[0]);
        String model = args[1];
        boolean editable = true;
        boolean pressOk = false;
        Map<String, String> typed = new LinkedHashMap<>();
        for (int i = 2; i < args.length; i++) {
            if (args[i].equals("readonly")) {
                editable = false;
            } else if (args[i].equals("ok")) {
                pressOk = true;
            } else {
                int eq = args[i].indexOf('=');
                typed.put(args[i].substring(0, eq), args[i].substring(eq + 1));
            }
        }
        Preferences root = TestPreferences.create();
        try {
            boolean finalEditable = editable;
            DistanceModelDialog[] dialog = new DistanceModelDialog[1];
            SimulatorModel simulatorModel = model.equals("ObstaclePropagationModel") ? new ObstaclePropagationModel()
                    : new DistanceOnlyPropagationModel();
            SwingUtilities.invokeAndWait(() -> dialog[0] = new DistanceModelDialog(null, simulatorModel, finalEditable,
                    new ModelPreferences(root)));
            SwingUtilities.invokeLater(() -> dialog[0].setVisible(true));
            Gui.until("the dialog shows", () -> dialog[0].isShowing());
            for (Map.Entry<String, String> entry : typed.entrySet()) {
                Gui.run(() -> Gui.find(dialog[0], JTextField.class, entry.getKey()).setText(entry.getValue()));
            }
            if (pressOk) {
                Gui.run(() -> Gui.find(dialog[0], JButton.class, DistanceModelDialog.OK).doClick());
            }
            Robot robot = new Robot();
            robot.waitForIdle();
            robot.delay(300); // let the window manager, if any, draw its frame
            robot.waitForIdle();
            Rectangle bounds = Gui.onEdt(() -> dialog[0].getBounds());
            BufferedImage image = robot.createScreenCapture(bounds);
            ImageIO.write(image, "png", out);
            Gui.run(() -> dialog[0].dispose());
            System.out.println(out + ": " + image.getWidth() + "x" + image.getHeight() + ", dialog " + bounds);
        } finally {
            TestPreferences.remove(root);
            System.exit(0);
        }
    }
}
