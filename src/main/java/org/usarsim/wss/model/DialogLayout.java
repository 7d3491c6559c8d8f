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
     * The DistanceOnly model's layout (the original's, with where positions come from): "Positions",
     * "USARSim Connection", "rosbridge", "Signal Strength Computation Parameters", the cutoff
     * distance computed both ways, "Link Stability" and "Shadowing". It shows positions, positions.interval,
     * usarsim.host, usarsim.port, usarsim.timeout, the rosbridge.* keys (url, topic, type, frame,
     * names, stale, maxMessage), distance.cutoff, distance.n, distance.pd0, distance.d0,
     * distance.margin, distance.holdTime, and "Shadowing": shadowing.sigma and shadowing.distance
     * (the seed is the run's, wss.seed): a model that does not declare every one of them gets
     * {@link #GENERATED}.
     */
    DISTANCE,

    /**
     * {@link #DISTANCE} with an "Obstacles" group: obstacle.attenuation, obstacle.cacheDistance,
     * obstacle.walls and rosbridge.map too (the Obstacle model's).
     */
    DISTANCE_AND_OBSTACLES
}
