package org.usarsim.wss.model.rfcomms;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
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
 * ({@link RfChannel#meanPower}); a link is up while it is at least the cutoff (the noise floor by
 * default) and within max_range. With links shaped, the pair's rate is the radio's capacity
 * (delay 0: RFComms has none) and each datagram of a fixed UDP port goes through RFComms' own
 * steps ({@link #datagramLoss}): the sender radio's 1 s capacity window, the power drawn, the BER
 * and the loss draw, the receiver's window. Walls are not counted, as RFComms counts none.
 */
public class RfCommsPropagationModel extends SimulatorModel {

    static final String TX_POWER = "rfcomms.txPower";
    static final String NOISE_FLOOR = "rfcomms.noiseFloor";
    static final String L0 = "rfcomms.l0";
    static final String FADING_EXPONENT = "rfcomms.fadingExponent";
    static final String SIGMA = "rfcomms.sigma";
    static final String MAX_RANGE = "rfcomms.maxRange";
    static final String CAPACITY = "rfcomms.capacity";
    static final String CUTOFF = "distance.cutoff";

    /** The simulator models' keys this model has no use for: the log-distance formula's and the shadowing's. */
    private static final Set<String> NOT_USED = Set.of("distance.pd0", "distance.n", "distance.d0", "shadowing.sigma",
            "shadowing.distance");

    private final RfChannel defaults;
    private final List<Setting> settings;
    /** The channel of the current run (the defaults before the first start). */
    private volatile RfChannel channel;
    /** Each robot's radio's capacity windows, sending and receiving, of the current run. */
    private volatile Map<String, CapacityWindow> sending = new ConcurrentHashMap<>();
    private volatile Map<String, CapacityWindow> receiving = new ConcurrentHashMap<>();
    /** Each way's loss rule, made once a run: the same rule each time the hub asks, so its condition does not change. */
    private volatile Map<List<String>, DatagramLoss> rules = new ConcurrentHashMap<>();

    /** gz-sim's RFComms defaults, on the machine's clock. */
    public RfCommsPropagationModel() {
        this(RfChannel.GZ_SIM, PollClock.SYSTEM);
    }

    /** gz-sim's RFComms defaults; the poller takes its time from {@code clock}. */
    public RfCommsPropagationModel(PollClock clock) {
        this(RfChannel.GZ_SIM, clock);
    }

    /** A preset: these defaults (SubT's, say). */
    protected RfCommsPropagationModel(RfChannel defaults, PollClock clock) {
        super(clock);
        this.defaults = defaults;
        this.channel = defaults;
        this.settings = declare(super.settings(), defaults);
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

    /** Where the positions come from and the link stability (the simulator models'), the cutoff, then RFComms' parameters. */
    @Override
    public List<Setting> settings() {
        return settings;
    }

    private static List<Setting> declare(List<Setting> simulator, RfChannel d) {
        List<Setting> all = new ArrayList<>();
        for (Setting setting : simulator) {
            if (setting.key().equals(CUTOFF)) {
                all.add(Setting.number(CUTOFF, "Link cutoff", plain(d.noiseFloor())).unit("dBm")
                        .help("A link (TCP) is up while the mean received power is at least this, within the max range;"
                                + " datagrams on fixed UDP ports are lost by RFComms' bit error rate instead"));
            } else if (!NOT_USED.contains(setting.key())) {
                all.add(setting);
            }
        }
        all.add(Setting.number(TX_POWER, "Transmit power", plain(d.txPower())).unit("dBm").help("radio_config/tx_power"));
        all.add(Setting.number(NOISE_FLOOR, "Noise floor", plain(d.noiseFloor())).unit("dBm").help("radio_config/noise_floor"));
        all.add(Setting.number(L0, "Path loss at 1 m", plain(d.l0())).unit("dB").help("range_config/l0"));
        all.add(Setting.number(FADING_EXPONENT, "Fading exponent", plain(d.fadingExponent())).above(0)
                .help("range_config/fading_exponent"));
        all.add(Setting.number(SIGMA, "Sigma", plain(d.sigma())).from(0)
                .help("range_config/sigma: the variance of each message's received power, in dB^2, as RFComms uses it"
                        + " (its standard deviation is the square root: 3.16 dB for 10)"));
        all.add(Setting.number(MAX_RANGE, "Max range", plain(d.maxRange())).from(0).unit("m").note("0: none")
                .help("range_config/max_range: beyond it nothing passes"));
        all.add(Setting.number(CAPACITY, "Capacity", plain(d.capacity())).above(0).unit("bit/s")
                .help("radio_config/capacity: the bits a radio sends, and receives, in any 1 s; a shaped link's rate"));
        return List.copyOf(all);
    }

    private static String plain(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value) : Double.toString(value);
    }

    @Override
    protected void started(ModelSettings values) throws ModelStartException {
        channel = new RfChannel(values.getDouble(TX_POWER, defaults.txPower()), values.getDouble(NOISE_FLOOR, defaults.noiseFloor()),
                values.getDouble(L0, defaults.l0()), values.getDouble(FADING_EXPONENT, defaults.fadingExponent()),
                values.getDouble(SIGMA, defaults.sigma()), values.getDouble(MAX_RANGE, defaults.maxRange()),
                values.getDouble(CAPACITY, defaults.capacity()));
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

    @Override
    protected boolean allowsUnknownRobots() {
        return false;
    }

    @Override
    protected boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed) {
        return !listed.isEmpty();
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
            if (channel.lost(a.get().distanceTo(b.get()), bytes, random)) {
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
