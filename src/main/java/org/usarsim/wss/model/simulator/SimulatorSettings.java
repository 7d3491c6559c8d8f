package org.usarsim.wss.model.simulator;

import java.util.List;
import org.usarsim.wss.model.Setting;

/**
 * The settings of every simulator model (DistanceOnly, Obstacle): where the positions come from
 * ({@code positions.*}, the simulator's socket {@code usarsim.*}, or {@code rosbridge.*}), the path
 * loss, the link stability. Declared here, read at each start by {@link SimulatorConfig}.
 */
final class SimulatorSettings {

    private SimulatorSettings() {
    }

    /** Every setting, in the order of the dialog and of {@code --help}. */
    static final List<Setting> ALL = List.of(
            Setting.choice("positions", "Positions from", SimulatorModel.USARSIM, List.of(SimulatorModel.USARSIM, SimulatorModel.ROSBRIDGE))
                    .help("Where the robots' positions come from: a USARSim-compatible position socket (usarsim.*)"
                            + " or a rosbridge WebSocket (rosbridge.*, docs/ros.md)"),
            Setting.integer("positions.interval", "Poll interval", 1000).from(100).to(60000).unit("ms").alias("usarsim.interval")
                    .help("Milliseconds between two applications of the robots' positions: a GETPOS,"
                            + " or the newest poses rosbridge sent (formerly usarsim.interval)"),
            Setting.host("usarsim.host", "Host", "127.0.0.1")
                    .help("The machine of the simulator's position socket: a host name or an IP address"),
            Setting.integer("usarsim.port", "Port", 7435).from(1).to(65535).noun("a port number")
                    .help("The simulator's position port, 7435 as a rule; not 3000, which is USARSim's robot port"),
            Setting.integer("usarsim.timeout", "Timeout", 2000).from(100).to(60000).unit("ms")
                    .help("Milliseconds to wait for the simulator's answer"),
            Setting.text("rosbridge.url", "URL", RosbridgeConfig.DEFAULT_URL)
                    .help("The rosbridge server's WebSocket: ws://HOST:PORT (rosbridge_server's default port is 9090)"),
            Setting.text("rosbridge.topic", "Topic", RosbridgeConfig.DEFAULT_TOPIC)
                    .help("The topic of the poses: /gazebo/model_states, /tf, or a per-robot one such as /{robot}/odom"),
            Setting.choice("rosbridge.type", "Message type", "", RosbridgeConfig.TYPES).orEmpty("by the topic")
                    .help("The topic's message type, where its name does not tell"),
            Setting.text("rosbridge.frame", "Frame", RosbridgeConfig.DEFAULT_FRAME)
                    .help("On /tf: the frame positions are in; each robot's chain of transforms is composed up to it"),
            Setting.text("rosbridge.names", "Names", "").orEmpty("the WSS names")
                    .help("WSS robot names to model names or frames, WSS=MODEL separated by commas (Scout=scout_1);"
                            + " others by their WSS name, or {robot}/base_link on /tf"),
            Setting.integer("rosbridge.stale", "Stale limit", 0).from(0).to(600000).unit("ms").note("0: 3 poll intervals")
                    .help("A robot whose pose is older is unlisted (kicked); nothing at all for this long: rosbridge is silent"),
            Setting.integer("rosbridge.grace", "Grace", RosbridgeConfig.DEFAULT_GRACE_MS).from(RosbridgeConfig.LEAST_GRACE_MS)
                    .to(600000).unit("ms")
                    .help("How long a registered robot's first pose is waited for before it is kicked as unlisted"
                            + " (its own topic subscribed as it registers, its publisher started late), and a new connection's"
                            + " first message before rosbridge counts as silent"),
            Setting.integer("rosbridge.maxMessage", "Largest message", 16).from(1).to(1024).unit("MiB")
                    .help("A longer message from rosbridge (its fragments together) is dropped with a line in the log"),
            Setting.number("distance.cutoff", "Cutoff", "-93").unit("dBm")
                    .help("Below this signal strength two robots cannot talk; -93 dBm is a property of the channel, best left as it is"),
            Setting.number("distance.pd0", "Pd0", "-49.67").unit("dBm").help("The signal strength at distance d0"),
            Setting.number("distance.n", "N", "1").above(0)
                    .help("The attenuation factor of the environment: how fast the signal fades with distance"),
            Setting.number("distance.d0", "d0", "2").above(0).unit("m").help("The distance at which the strength is Pd0"),
            Setting.number("distance.margin", "Margin", "0").from(0).unit("dB")
                    .help("A broken link resumes only when the strength is above Cutoff + Margin, so that a pair at the edge does not flap"),
            Setting.number("distance.holdTime", "Hold time", "0").from(0).unit("s")
                    .help("A link stays broken, or resumed, at least this many seconds before it changes again"),
            Setting.number(Shadowing.SIGMA, "Shadowing sigma", "0").from(0).to(30).unit("dB").note("0: none")
                    .help("Log-normal shadowing: a term of this standard deviation added to each pair's strength,"
                            + " correlated in space (docs/models.md, \"Shadowing\"); 10 dB indoors"),
            Setting.number(Shadowing.DISTANCE, "Decorrelation distance", "5").above(0).unit("m")
                    .help("How far a robot moves before its shadowing is unrelated to the one it left (Gudmundson's model):"
                            + " 5 m indoors, 50 m outdoors"));
}
