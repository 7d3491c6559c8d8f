package org.usarsim.wss.model.rfcomms;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.ConcurrentHashMap;
import java.util.random.RandomGenerator;
import org.usarsim.wss.model.DatagramLoss;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.LinkQuality;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.simulator.PollClock;
import org.usarsim.wss.model.simulator.ReportedRobot;
import org.usarsim.wss.model.simulator.SimulatorModel;

/**
 * gz-sim's RFComms as a WSS model (docs/models.md, "RFComms and SubT"), positions from the
 * simulator models' sources: a pair's strength is RFComms' mean received power
 * ({@link RfChannel#meanPower}); a link is up within max_range while that power is at least
 * the cutoff ({@code distance.cutoff}, -93 dBm as the other models'; RFComms has none). Its
 * parameters take a preset's values ({@code rfcomms.preset}: gz-sim's RFComms, or the SubT
 * simulator's: 20 dBm, 1 Mbit/s, 500 m; SubT's visibility cost is not modelled, docs/models.md). With links shaped, the pair's rate is the radio's capacity
 * (delay 0: RFComms has none) and each datagram of a fixed UDP port goes through RFComms' own
 * steps ({@link #datagramLoss}): the sender radio's 1 s capacity window, the power drawn, the BER
 * and the loss draw, the receiver's window. Walls are not counted, as RFComms counts none.
 */
public class RfCommsPropagationModel extends SimulatorModel {

    static final String PRESET = "rfcomms.preset";
    static final String TX_POWER = "rfcomms.txPower";
    static final String NOISE_FLOOR = "rfcomms.noiseFloor";
    static final String L0 = "rfcomms.l0";
    static final String FADING_EXPONENT = "rfcomms.fadingExponent";
    static final String SIGMA = "rfcomms.sigma";
    static final String MAX_RANGE = "rfcomms.maxRange";
    static final String CAPACITY = "rfcomms.capacity";

    /** The presets, by the value of rfcomms.preset: gz-sim's defaults and the SubT simulator's. */
    static final Map<String, RfChannel> PRESETS = Map.of("gz-sim", RfChannel.GZ_SIM, "subt", RfChannel.SUBT);

    /** The simulator models' keys this model has no use for: the log-distance formula's and the shadowing's (the run's wss.seed it uses). */
    private static final Set<String> NOT_USED = Set.of("distance.pd0", "distance.n", "distance.d0", "shadowing.sigma",
            "shadowing.distance");

    private final List<Setting> settings = declare(super.settings());
    /** The channel of the current run (gz-sim's before the first start). */
    private volatile RfChannel channel = RfChannel.GZ_SIM;
    /** The run's wss.seed, mixed into every datagram's draws. */
    private volatile long seed;
    /** Each robot's radio's capacity windows, sending and receiving, of the current run. */
    private volatile Map<String, CapacityWindow> sending = new ConcurrentHashMap<>();
    private volatile Map<String, CapacityWindow> receiving = new ConcurrentHashMap<>();
    /** Each way's loss rule, made once a run: the same rule each time the hub asks, so its condition does not change. */
    private volatile Map<List<String>, DatagramLoss> rules = new ConcurrentHashMap<>();

    /** On the machine's clock. */
    public RfCommsPropagationModel() {
    }

    /** The poller takes its time from {@code clock}. */
    public RfCommsPropagationModel(PollClock clock) {
        super(clock);
    }

    @Override
    public String name() {
        return "RFComms";
    }

    /** The generated dialog: a row per setting (the distance layout shows the log-distance formula's keys, not RFComms'). */
    @Override
    public DialogLayout dialogLayout() {
        return DialogLayout.GENERATED;
    }

    /** Where the positions come from, the cutoff and the link stability (the simulator models'), then RFComms' parameters. */
    @Override
    public List<Setting> settings() {
        return settings;
    }

    private static List<Setting> declare(List<Setting> simulator) {
        List<Setting> all = new ArrayList<>();
        simulator.stream().filter(setting -> !NOT_USED.contains(setting.key())).forEach(all::add);
        all.add(Setting.choice(PRESET, "Preset", "gz-sim", List.of("gz-sim", "subt"))
                .help("Whose defaults the empty parameters below take: gz-sim's RFComms, or the DARPA SubT simulator's"));
        all.add(parameter(TX_POWER, "Transmit power", "dBm", "radio_config/tx_power", RfChannel::txPower));
        all.add(parameter(NOISE_FLOOR, "Noise floor", "dBm", "radio_config/noise_floor", RfChannel::noiseFloor));
        all.add(parameter(L0, "Path loss at 1 m", "dB", "range_config/l0", RfChannel::l0));
        all.add(parameter(FADING_EXPONENT, "Fading exponent", null, "range_config/fading_exponent", RfChannel::fadingExponent).above(0));
        all.add(parameter(SIGMA, "Sigma", null, "range_config/sigma: the variance of each message's received power in dB^2,"
                + " as RFComms uses it (its standard deviation is the square root: 3.16 dB for 10)", RfChannel::sigma).from(0));
        all.add(parameter(MAX_RANGE, "Max range", "m", "range_config/max_range: beyond it nothing passes; 0: no limit",
                RfChannel::maxRange).from(0));
        all.add(parameter(CAPACITY, "Capacity", "bit/s", "radio_config/capacity: the bits a radio sends, and receives, in any"
                + " 1 s; a shaped link's rate", RfChannel::capacity).above(0));
        return List.copyOf(all);
    }

    /** A parameter whose empty value (the default) is the preset's. */
    private static Setting parameter(String key, String label, String unit, String help,
            java.util.function.ToDoubleFunction<RfChannel> value) {
        Setting setting = Setting.number(key, label, "").orEmpty("the preset's, " + plain(value.applyAsDouble(RfChannel.GZ_SIM))
                + " (gz-sim) or " + plain(value.applyAsDouble(RfChannel.SUBT)) + " (SubT)").help(help);
        return unit == null ? setting : setting.unit(unit);
    }

    private static String plain(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value) : Double.toString(value);
    }

    /** The run's channel: the preset's parameters, each one given instead. */
    static RfChannel channelOf(ModelSettings values) {
        RfChannel preset = PRESETS.getOrDefault(values.getString(PRESET, "gz-sim"), RfChannel.GZ_SIM);
        return new RfChannel(given(values, TX_POWER, preset.txPower()), given(values, NOISE_FLOOR, preset.noiseFloor()),
                given(values, L0, preset.l0()), given(values, FADING_EXPONENT, preset.fadingExponent()),
                given(values, SIGMA, preset.sigma()), given(values, MAX_RANGE, preset.maxRange()),
                given(values, CAPACITY, preset.capacity()));
    }

    private static double given(ModelSettings values, String key, double preset) {
        String value = values.getString(key, "").strip();
        return value.isEmpty() ? preset : Double.parseDouble(value);
    }

    @Override
    protected void started(ModelSettings values) throws ModelStartException {
        channel = channelOf(values);
        seed = values.getLong(ModelSettings.SEED, 0) * 0x9E3779B97F4A7C15L;
        sending = new ConcurrentHashMap<>();
        receiving = new ConcurrentHashMap<>();
        rules = new ConcurrentHashMap<>();
    }

    /** The channel of the current run. */
    RfChannel channel() {
        return channel;
    }

    /** RFComms' mean received power at the pair's distance; walls do not count. */
    @Override
    protected double strength(ReportedRobot a, ReportedRobot b, double obstacles) {
        return channel.meanPower(a.distanceTo(b));
    }

    /** Where the mean power reaches the cutoff, no farther than the max range. */
    @Override
    protected double range(double obstacles) {
        RfChannel run = channel;
        double range = Math.pow(10, (run.txPower() - run.l0() - cutoff()) / (10 * run.fadingExponent()));
        return run.maxRange() > 0 ? Math.min(range, run.maxRange()) : range;
    }

    /** With links shaped: the capacity as the rate, no delay, and RFComms' datagram losses. */
    @Override
    public Optional<LinkQuality> linkQualityForPair(String from, String to) {
        long rate = Math.max(1, Math.round(channel.capacity()));
        return Optional.of(new LinkQuality(rate, 0, rules.computeIfAbsent(List.of(from, to), way -> datagramLoss(from, to))));
    }

    /**
     * RFComms' AttemptSend for a datagram from {@code from} to {@code to}: refused when the sender's
     * window is full (else counted there), lost by the drawn power's BER at the distance the last
     * poll knew (lost when either position is unknown), refused when the receiver's window is full.
     * The draws come from the port's generator and {@code wss.seed}: the same traffic and seeds
     * lose the same datagrams.
     */
    DatagramLoss datagramLoss(String from, String to) {
        return (int bytes, long nowNs, RandomGenerator random) -> {
            Optional<Position> a = positionOf(from);
            Optional<Position> b = positionOf(to);
            if (a.isEmpty() || b.isEmpty()) {
                return true;
            }
            if (!admitted(sending, from, nowNs, bytes)) {
                return true;
            }
            // the port's generator gives the datagram's own, which wss.seed changes: the draws depend on both seeds alone
            if (channel.lost(a.get().distanceTo(b.get()), bytes, new SplittableRandom(random.nextLong() ^ seed))) {
                return true;
            }
            return !admitted(receiving, to, nowNs, bytes);
        };
    }

    private boolean admitted(Map<String, CapacityWindow> windows, String robot, long nowNs, int bytes) {
        CapacityWindow window = windows.computeIfAbsent(robot, r -> new CapacityWindow(channel.capacity()));
        synchronized (window) {
            return window.admit(nowNs, bytes);
        }
    }
}
