package org.usarsim.wss.gui;

import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.prefs.Preferences;
import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.PluginJars;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.simulator.SimulatorModel;
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
 *     DistanceOnlyPropagationModel|ObstaclePropagationModel|Tuned [readonly] [key=value ...] [ok]'
 * </pre>
 *
 * <p>{@code Tuned} is the test plugin that declares two settings ({@link PluginJars#TUNED}),
 * compiled and loaded from a jar as a plugin is, shown in the dialog built from its declaration.
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
            JDialog[] dialog = new JDialog[1];
            PropagationModel shown = switch (model) {
                case "ObstaclePropagationModel" -> new ObstaclePropagationModel();
                case "Tuned" -> tunedPlugin();
                default -> new DistanceOnlyPropagationModel();
            };
            ModelPreferences preferences = new ModelPreferences(root);
            SwingUtilities.invokeAndWait(() -> dialog[0] = shown instanceof SimulatorModel simulatorModel
                    ? new DistanceModelDialog(null, simulatorModel, finalEditable, preferences, preferences.load(shown))
                    : new GeneratedModelDialog(null, shown, finalEditable, preferences, preferences.load(shown)));
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

    /** The test plugin Tuned, compiled, jarred and loaded from its jar as the server loads a plugin. */
    private static PropagationModel tunedPlugin() throws IOException {
        Path dir = Files.createTempDirectory("wss-screenshot");
        Path classes = PluginJars.compile(dir);
        PluginJars.tunedJar(dir.resolve("plugins").resolve("tuned.jar"), classes);
        return ModelCatalog.load(DialogScreenshot.class.getClassLoader(), List.of(dir.resolve("plugins"))).find("Tuned");
    }
}
