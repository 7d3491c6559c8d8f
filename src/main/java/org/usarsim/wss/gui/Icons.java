package org.usarsim.wss.gui;

import java.awt.Image;
import java.net.URL;
import java.util.List;
import java.util.Objects;
import javax.swing.ImageIcon;

/**
 * The WSS's icon, a radio mast between two robots, at 48 and 256 pixels ({@code wss-48.png},
 * {@code wss-256.png} beside this class; drawn by the test tree's {@code IconDrawing}). The
 * window's icon, the About dialog's, and the desktop menu's in the Debian package.
 */
final class Icons {

    static final List<Integer> SIZES = List.of(48, 256);

    private Icons() {
    }

    /** The icon of that size (one of {@link #SIZES}); null when it is missing from the classpath. */
    static ImageIcon of(int size) {
        URL url = Icons.class.getResource("wss-" + size + ".png");
        return url == null ? null : new ImageIcon(url);
    }

    /** Every size there is, for {@code Window.setIconImages}. */
    static List<Image> all() {
        return SIZES.stream().map(Icons::of).filter(Objects::nonNull).map(ImageIcon::getImage).toList();
    }
}
