package org.usarsim.wss.model;

import java.util.List;
import java.util.Optional;

/**
 * A propagation model decides, for every pair of robots, the signal strength between them and
 * whether they may talk. Implementations are found with {@link java.util.ServiceLoader}: list the
 * class in {@code META-INF/services/org.usarsim.wss.model.PropagationModel}. See docs/models.md.
 *
 * <p>Lifecycle, driven by the server: {@link #configure}, {@link #setRobotLinkModel},
 * {@link #setEventListener}, then {@link #start}; {@link #shutdown} when the server stops.
 * The query methods are called from many threads at once and must be thread-safe and quick
 * (they are asked on every GETSS, DNS and accepted connection). A model must not call the
 * {@link RobotLinkModel} from inside a query method.
 */
public interface PropagationModel {

    /** The name users pick the model by; the class's simple name unless overridden. */
    default String name() {
        return getClass().getSimpleName();
    }

    /**
     * The settings the model takes, declared once: headless accepts their keys in the properties
     * file, the GUI builds a dialog from them, both check every value with {@link Setting#problem}.
     * None by default. Keys are the model's own ({@code mymodel.gain}); {@code wss.*} is the
     * server's. See docs/models.md.
     */
    default List<Setting> settings() {
        return List.of();
    }

    /**
     * Takes the settings (headless: the properties file; GUI: the stored preferences): a value for
     * every key of {@link #settings()}, checked with its rule, the default where none was given.
     */
    default void configure(ModelSettings settings) {
    }

    /** The hub, for breaking and resuming pairs and kicking robots. Called before {@link #start}. */
    void setRobotLinkModel(RobotLinkModel linkModel);

    /** Where the model reports what it decides (out of range, in range, out of battery). */
    void setEventListener(WssEventListener listener);

    /**
     * Checks the configuration and starts the model (its own threads, its simulator connection).
     *
     * @throws ModelStartException when the configuration is bad or a resource is unreachable; the
     *                             message is shown to the user as it is
     */
    void start() throws ModelStartException;

    /** Stops the model's threads and connections. */
    void shutdown();

    boolean isActive();

    /**
     * Whether {@link #showConfigurationDialog} shows a dialog of the model's own, which the GUI
     * then opens instead of the one it builds from {@link #settings()}.
     */
    default boolean isConfigurable() {
        return false;
    }

    /** Shows the model's settings; read-only when {@code editable} is false (the server runs). */
    default void showConfigurationDialog(boolean editable) {
    }

    /**
     * Which dialog the GUI builds from {@link #settings()} to configure the model: by default the
     * one generated from the declaration, a row per setting; {@link DialogLayout#DISTANCE} or
     * {@link DialogLayout#DISTANCE_AND_OBSTACLES} for the simulator models' layout, which the GUI
     * uses when the model declares every key that layout shows. Not asked when
     * {@link #isConfigurable()}.
     */
    default DialogLayout dialogLayout() {
        return DialogLayout.GENERATED;
    }

    /**
     * The signal strength from {@code from} to {@code to} in dBm. NaN when unknown;
     * {@code +Infinity} when the robots are at the same place.
     */
    double getSignalStrengthForPair(String from, String to);

    /** Whether {@code from} may open a connection to {@code to} now. */
    boolean connectionIsPossibleForPair(String from, String to);

    /**
     * The link's rate and delay from {@code from} to {@code to}, when links are shaped
     * ({@code wss.shaping = on}, docs/shaping.md); empty (the default) leaves them to the
     * server's rate table (from the strength) and delay. Asked without the server's locks, a few
     * times a second per pair with a WSS port; existing plugins need not know it.
     */
    default Optional<LinkQuality> linkQualityForPair(String from, String to) {
        return Optional.empty();
    }

    /**
     * Where the robot is, as the model last learned it (the map and the per-link statistics show
     * it). Empty when the model does not know positions (Noop) or the robot is not in the simulator.
     */
    default Optional<Position> positionOf(String robot) {
        return Optional.empty();
    }

    /**
     * The distance in metres from {@code from} at which the strength to {@code to} reaches the
     * model's cutoff (the map draws it as a circle). NaN when the model has no such range.
     */
    default double rangeFor(String from, String to) {
        return Double.NaN;
    }

    /**
     * The walls the model knows, seen from above (the map draws them). Empty when the model has no
     * simulator or the simulator does not give its walls (USARSim does not).
     */
    default List<Wall> walls() {
        return List.of();
    }

    /**
     * The strength in dBm below which the model breaks a pair (the map colours a pair near it
     * amber). NaN when the model has no such cutoff.
     */
    default double cutoff() {
        return Double.NaN;
    }

    /**
     * The replay's controls when the model replays a recording (docs/replay.md): the window shows
     * its time bar, the operator's {@code REPLAY} command moves it. Empty (the default) otherwise.
     */
    default Optional<Replay> replay() {
        return Optional.empty();
    }
}
