package org.usarsim.wss.recording;

import java.nio.file.Path;
import java.util.AbstractList;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.RandomAccess;
import java.util.logging.Logger;
import org.usarsim.wss.model.ModelPoll;

/**
 * A recording's polls, each read from the file's bytes the first time it is asked for (the last
 * few kept): opening a long recording costs a pass over its lines, not reading 700,000 rows. A
 * poll whose rows cannot be read (a file edited by hand) is said once and replaced by the poll
 * before it: the network holds as it was. Thread-safe.
 */
final class LazyPolls extends AbstractList<Entry.Poll> implements RandomAccess {

    private static final Logger LOG = Logger.getLogger(RecordingReader.class.getName());
    private static final int KEPT = 16;

    /** Where a poll's rows are: its time, the offset and line number of its first row, its rows. */
    record At(long millis, int offset, int line, int robots, int pairs) {
    }

    private final Path file;
    private final byte[] data;
    private final List<At> index;
    private final Map<String, String> names = new HashMap<>();
    private final Map<Integer, Entry.Poll> kept = new LinkedHashMap<>(KEPT * 2, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Integer, Entry.Poll> eldest) {
            return size() > KEPT;
        }
    };

    LazyPolls(Path file, byte[] data, List<At> index) {
        this.file = file;
        this.data = data;
        this.index = List.copyOf(index);
    }

    @Override
    public int size() {
        return index.size();
    }

    /** The poll's time, without reading its rows. */
    long millis(int i) {
        return index.get(i).millis();
    }

    @Override
    public synchronized Entry.Poll get(int i) {
        Entry.Poll poll = kept.get(i);
        if (poll == null) {
            poll = read(i);
            kept.put(i, poll);
        }
        return poll;
    }

    private Entry.Poll read(int i) {
        At at = index.get(i);
        RecordingReader.ByteLines lines = new RecordingReader.ByteLines(data, at.offset(), data.length);
        List<ModelPoll.Robot> robots = new ArrayList<>(at.robots());
        List<ModelPoll.Pair> pairs = new ArrayList<>(at.pairs());
        for (int row = 0; row < at.robots() + at.pairs(); row++) {
            lines.next();
            EntryLines.Line line;
            try {
                line = EntryLines.read(lines.text());
            } catch (IllegalArgumentException e) {
                LOG.warning(file + " line " + (at.line() + row) + " cannot be read (" + e.getMessage()
                        + "): the poll at " + at.millis() + " ms is replaced by the one before it");
                return i == 0 ? new Entry.Poll(at.millis(), List.of(), List.of()) : withTime(get(i - 1), at.millis());
            }
            if (line instanceof EntryLines.RobotRow r) {
                robots.add(new ModelPoll.Robot(name(r.robot().name()), r.robot().position(), r.robot().batteryEmpty()));
            } else if (line instanceof EntryLines.PairRow p) {
                ModelPoll.Pair pair = p.pair();
                pairs.add(new ModelPoll.Pair(name(pair.first()), name(pair.second()), pair.strength(), pair.obstacles(), pair.live()));
            }
        }
        return new Entry.Poll(at.millis(), robots, pairs);
    }

    private static Entry.Poll withTime(Entry.Poll poll, long millis) {
        return new Entry.Poll(millis, poll.robots(), poll.pairs());
    }

    private String name(String name) {
        return names.computeIfAbsent(name, n -> n);
    }
}
