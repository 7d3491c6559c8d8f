package org.usarsim.wss.model.obstacle;

import java.util.List;
import org.usarsim.wss.world.WorldWalls;

/**
 * The Obstacle model's wall-loss term, for the walls of {@code obstacle.walls}: the sum of the
 * losses of the walls a line crosses, each by its material ({@code obstacle.loss}); a wall of no
 * material loses the model's attenuation. Summed as count times loss per material, in the order
 * the materials were first met, so that walls of one material whose loss is the attenuation lose
 * exactly {@code count * attenuation}, today's term to the last bit. Immutable.
 */
final class WallLoss {

    /** The walls a line crossed and what they cost. */
    record Crossing(int count, double lossDb) {
    }

    private final WorldWalls walls;
    /** Per material of {@link WorldWalls#materials()}: the loss of one wall. */
    private final double[] losses;

    /** Refused (IllegalArgumentException, naming it) when a wall's material has no loss given. */
    WallLoss(WorldWalls walls, MaterialLosses given, double attenuation) {
        this.walls = walls;
        List<String> materials = walls.materials();
        losses = new double[materials.size()];
        for (int i = 0; i < losses.length; i++) {
            String material = materials.get(i);
            Double loss = material.isEmpty() ? Double.valueOf(attenuation) : given.of(material);
            if (loss == null) {
                throw new IllegalArgumentException("walls of " + material + ", which has no loss in obstacle.loss");
            }
            losses[i] = loss;
        }
    }

    /** The walls between (ax, ay) and (bx, by) on the floor and the sum of their losses in dB. */
    Crossing between(double ax, double ay, double bx, double by) {
        int[] counts = new int[losses.length];
        walls.crossed(ax, ay, bx, by, counts);
        int count = 0;
        double loss = 0;
        for (int i = 0; i < counts.length; i++) {
            if (counts[i] > 0) {
                count += counts[i];
                loss += counts[i] * losses[i];
            }
        }
        return new Crossing(count, loss);
    }
}
