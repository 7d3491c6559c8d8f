package org.usarsim.wss.model.obstacle;

import java.nio.file.Path;
import org.usarsim.wss.model.ModelInputException;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.world.MaterialRules;
import org.usarsim.wss.world.WorldFileException;
import org.usarsim.wss.world.WorldWalls;

/**
 * The settings of the walls the Obstacle model counts itself (docs/models.md, "Materials"):
 * {@code obstacle.materials} (an SDF world's names to materials), {@code obstacle.loss} (the loss
 * of a wall of each material) and {@code obstacle.heightBand} (which boxes of an SDF world are
 * walls), read and checked at a start.
 */
record WallSettings(MaterialRules rules, MaterialLosses losses, double low, double high) {

    /** The 2019 Virtual Robot League's wall kinds (model names), then glass, then concrete. */
    static final String MATERIALS = "Hard_wall*=concrete, Medium_wall*=brick, Soft_wall*=drywall, *glass*=glass, *=concrete";
    /** COST-231 multi-wall as ns-3's buildings module documents it, and the 2019 WCS's kinds (docs/models.md). */
    static final String LOSSES = "concrete:15, brick:10, drywall:4, wood:4, glass:2, metal:30";
    /** A robot's radio from the floor up to a person's height. */
    static final String BAND = "0.1..2.0";

    /** The run's values, refused with the setting's name and what is wrong. */
    static WallSettings of(ModelSettings settings) throws ModelInputException {
        MaterialRules rules;
        MaterialLosses losses;
        try {
            rules = MaterialRules.parse(settings.getString("obstacle.materials", MATERIALS));
        } catch (IllegalArgumentException e) {
            throw new ModelInputException("obstacle.materials: " + e.getMessage());
        }
        try {
            losses = MaterialLosses.parse(settings.getString("obstacle.loss", LOSSES));
        } catch (IllegalArgumentException e) {
            throw new ModelInputException("obstacle.loss: " + e.getMessage());
        }
        String band = settings.getString("obstacle.heightBand", BAND).strip();
        int dots = band.indexOf("..");
        double low = dots < 0 ? Double.NaN : number(band.substring(0, dots));
        double high = dots < 0 ? Double.NaN : number(band.substring(dots + 2));
        if (!(low <= high) || Double.isInfinite(low) || Double.isInfinite(high)) {
            throw new ModelInputException("obstacle.heightBand: '" + band + "' is not LOW..HIGH in metres, LOW at most HIGH");
        }
        return new WallSettings(rules, losses, low, high);
    }

    private static double number(String text) {
        try {
            return Double.parseDouble(text.strip());
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /** The walls of this file (a world file, or an SDF world read with these rules and band). */
    WorldWalls walls(Path file) throws WorldFileException {
        return WorldWalls.read(file, rules, low, high);
    }
}
