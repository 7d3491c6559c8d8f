package org.usarsim.wss.recording;

import java.util.List;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Wall;

/**
 * One thing a recording holds, at its time in milliseconds from the start of the run
 * (docs/replay.md, "The format"): each kind is one line of the file, a poll a line and its robots'
 * and pairs' lines. {@link EntryLines} writes and reads them.
 */
public sealed interface Entry {

    long millis();

    /** A poll of the model: every robot listed, every pair of present robots. */
    record Poll(long millis, List<ModelPoll.Robot> robots, List<ModelPoll.Pair> pairs) implements Entry {
        public Poll {
            robots = List.copyOf(robots);
            pairs = List.copyOf(pairs);
        }
    }

    /** The simulator's walls, from now on (they replace the ones before). */
    record Walls(long millis, List<Wall> walls) implements Entry {
        public Walls {
            walls = List.copyOf(walls);
        }
    }

    /** The model kicked a registered robot out: its battery was empty, or the simulator did not list it. */
    record Kick(long millis, String robot, boolean batteryEmpty) implements Entry {
    }

    record Registered(long millis, String robot, String address) implements Entry {
    }

    record Left(long millis, String robot) implements Entry {
    }

    /** The model broke the pair: out of range at that strength (dBm) and distance (m). */
    record Break(long millis, String first, String second, double strength, double distance) implements Entry {
    }

    /** The model resumed the pair. */
    record Resume(long millis, String first, String second) implements Entry {
    }

    /** An operator forced the pair up or down. */
    record Force(long millis, String first, String second, boolean up) implements Entry {
    }

    /**
     * An operator pinned the shape of a pair forced up ({@code FORCE ... {Rate}{Delay}{Jitter}}): its
     * rate in bit/s (0: not pinned), delay and jitter in ms (-1: not pinned).
     */
    record Pin(long millis, String first, String second, long bitsPerSecond, int delayMs, int jitterMs) implements Entry {
    }

    /** An operator gave the pair back to the model. */
    record Release(long millis, String first, String second) implements Entry {
    }

    /** An operator moved the replay being recorded: where it is now (seconds), its speed, whether it plays. */
    record Replay(long millis, double timeSeconds, double speed, boolean playing) implements Entry {
    }

    /** With links shaped: the rate one way, set or changed. */
    record Rate(long millis, String from, String to, long bitsPerSecond) implements Entry {
    }

    /**
     * A fixed UDP port's datagrams one way since its last such entry (docs/fixed-ports.md): the
     * port's number on the WSS ({@link #NO_PORT} in a recording made before lines said it), sent,
     * their bytes, dropped because the pair was broken, dropped by its shaped queue, lost to the signal.
     */
    record Udp(long millis, String from, String to, int port, long datagrams, long bytes, long droppedBroken, long droppedQueue,
            long lost)
            implements Entry {

        /** The port of a line written before a {@code udp} line said its port (its 7 fields): not known. */
        public static final int NO_PORT = 0;
    }

    /** Entries the recorder could not queue since the last such line (its queue was full). */
    record Dropped(long millis, long count) implements Entry {
    }

    /** The run stopped; nothing follows. A file without it was cut short. */
    record End(long millis) implements Entry {
    }
}
