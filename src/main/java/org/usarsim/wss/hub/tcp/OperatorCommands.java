package org.usarsim.wss.hub.tcp;

import java.net.InetAddress;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.protocol.Arguments;
import org.usarsim.wss.protocol.Command;
import org.usarsim.wss.protocol.ProtocolException;
import org.usarsim.wss.protocol.Replies;
import org.usarsim.wss.shaping.Bitrate;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The operator's two commands, FORCE and REPLAY, as the control port and the monitor's POSTs
 * (docs/monitor.md) both answer them: the same checks, the same log line naming who asked, the same
 * reply. Whether the asker may use them (wss.operators, an operator's token) is the caller's to say.
 */
public final class OperatorCommands {

    private static final Logger LOG = Logger.getLogger(ControlSession.class.getName());

    private OperatorCommands() {
    }

    /**
     * The operator command (docs/protocol.md section 7): {@code FORCE {Robot A} {Peer B} {State Down|Up|Model}}, up with an optional {@code {Rate r} {Delay d} {Jitter j}}.
     * The names need not be registered. {@code who} names the asker in the log line ({@code address:port}).
     */
    public static String force(ControlHub hub, Command command, InetAddress address, String who) throws ProtocolException {
        List<String> pair = Arguments.pair(command);
        String first = pair.get(0);
        String second = pair.get(1);
        String state = command.value("State");
        String wanted = state == null ? "" : state.toLowerCase(Locale.ROOT);
        if (!List.of("down", "up", "model").contains(wanted)) {
            return Replies.error(Replies.STATE_MUST_BE_DOWN_UP_OR_MODEL);
        }
        String rateText = command.value("Rate");
        String delayText = command.value("Delay");
        String jitterText = command.value("Jitter");
        RatePin pin = RatePin.NONE;
        if (rateText != null || delayText != null || jitterText != null) {
            if (!wanted.equals("up")) {
                return Replies.error(Replies.RATE_AND_DELAY_NEED_STATE_UP);
            }
            long rate = 0;
            int delay = -1;
            try {
                rate = rateText == null ? 0 : Bitrate.parse(rateText);
            } catch (IllegalArgumentException e) {
                return Replies.error(Replies.RATE_MUST_BE_A_BIT_RATE);
            }
            try {
                delay = delayText == null ? -1 : ShapingConfig.parseDelayMs(delayText);
            } catch (IllegalArgumentException e) {
                return Replies.error(Replies.DELAY_MUST_BE_0_TO_10000_MS);
            }
            int jitter;
            try {
                jitter = jitterText == null ? -1 : ShapingConfig.parseJitterMs(jitterText);
            } catch (IllegalArgumentException e) {
                return Replies.error(Replies.JITTER_MUST_BE_0_TO_10000_MS);
            }
            pin = new RatePin(rate, delay, jitter);
        }
        String shape = pin.equals(RatePin.NONE) ? "" : (pin.pinsRate() ? " rate " + Bitrate.format(pin.bitsPerSecond()) : "")
                + (pin.pinsDelay() ? " delay " + pin.delayMs() + " ms" : "") + (pin.pinsJitter() ? " jitter " + pin.jitterMs() + " ms" : "");
        // Who, before what it does; limited like the WARNINGs, as an operator can send FORCEs as fast as it likes.
        hub.note(LOG, "operator commands", address, "operator " + who + ": FORCE " + first + " - " + second + " " + state + shape);
        switch (wanted) {
            case "down" -> hub.force(first, second, Force.DOWN);
            case "up" -> hub.force(first, second, Force.UP, pin);
            default -> hub.release(first, second);
        }
        return Replies.forceOk();
    }

    /**
     * The operator command REPLAY (docs/protocol.md section 8): {@code REPLAY {Time s} {Speed x} {State Pause|Play}},
     * any of them or none (then it only asks), only while the model replays a recording. Every field
     * is checked before anything changes.
     */
    public static String replay(ControlHub hub, Command command, InetAddress address, String who) throws ProtocolException {
        Optional<Replay> found = hub.replay();
        if (found.isEmpty()) {
            return Replies.error(Replies.NOT_A_REPLAY);
        }
        Replay replay = found.get();
        OptionalDouble time = Arguments.replayTime(command, replay.durationSeconds());
        OptionalDouble speed = Arguments.replaySpeed(command, Replay.MIN_SPEED, Replay.MAX_SPEED);
        Boolean play = Arguments.replayPlays(command);
        if (time.isPresent() || speed.isPresent() || play != null) {
            hub.note(LOG, "operator commands", address, "operator " + who + ": REPLAY"
                    + (time.isPresent() ? " time " + time.getAsDouble() + " s" : "")
                    + (speed.isPresent() ? " speed " + speed.getAsDouble() + "x" : "")
                    + (play == null ? "" : play ? " play" : " pause"));
        }
        if (speed.isPresent()) {
            replay.speed(speed.getAsDouble());
        }
        if (time.isPresent()) {
            replay.jump(time.getAsDouble());
        }
        if (play != null) {
            if (play) {
                replay.play();
            } else {
                replay.pause();
            }
        }
        return Replies.replayOk(replay.timeSeconds(), replay.durationSeconds(), replay.speed(), replay.playing(),
                replay.pollSeconds());
    }
}
