package org.usarsim.wss.model;

/**
 * Which configuration dialog the window builds for a model from its declared settings
 * ({@link PropagationModel#dialogLayout()}); words only, no Swing: the window lays the dialog out.
 * A model with a dialog of its own ({@link PropagationModel#isConfigurable()}) is shown that one
 * instead.
 */
public enum DialogLayout {

    /** A row per declared setting, in the order declared: fits any model. The default. */
    GENERATED,

    /**
     * The DistanceOnly model's layout (the original's): "USARSim Connection", "Signal Strength
     * Computation Parameters", the cutoff distance computed both ways, and "Link Stability". It
     * shows usarsim.host, usarsim.port, usarsim.interval, usarsim.timeout, distance.cutoff,
     * distance.n, distance.pd0, distance.d0, distance.margin and distance.holdTime: a model that
     * does not declare every one of them gets {@link #GENERATED}.
     */
    DISTANCE,

    /**
     * {@link #DISTANCE} with an "Obstacles" group: obstacle.attenuation and obstacle.cacheDistance
     * too (the Obstacle model's).
     */
    DISTANCE_AND_OBSTACLES
}
