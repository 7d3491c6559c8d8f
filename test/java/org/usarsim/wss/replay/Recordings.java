package org.usarsim.wss.replay;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.EntryLines;
import org.usarsim.wss.recording.Header;

/** Recordings written by hand for a test, through {@link EntryLines} (the one writer of the format). */
public final class Recordings {

    private final List<Entry> entries = new ArrayList<>();
    private final Map<String, String> settings = new LinkedHashMap<>();
    private final List<ModelPoll.Robot> robots = new ArrayList<>();
    private final List<ModelPoll.Pair> pairs = new ArrayList<>();

    public Recordings() {
        settings.put("usarsim.interval", "200");
        settings.put("distance.cutoff", "-93");
    }

    /** A robot of the poll being built. */
    public Recordings robot(String name, double x, double y, boolean batteryEmpty) {
        robots.add(new ModelPoll.Robot(name, new Position(x, y, 0), batteryEmpty));
        return this;
    }

    /** A pair of the poll being built. */
    public Recordings pair(String a, String b, double strength, boolean live) {
        pairs.add(new ModelPoll.Pair(a, b, strength, 0, live));
        return this;
    }

    /** Ends the poll being built at {@code millis}. */
    public Recordings poll(long millis) {
        entries.add(new Entry.Poll(millis, robots, pairs));
        robots.clear();
        pairs.clear();
        return this;
    }

    public Recordings entry(Entry entry) {
        entries.add(entry);
        return this;
    }

    /** The header and the entries, with an {@code end} at {@code endMillis} unless it is negative. */
    public String text(long endMillis) {
        StringBuilder text = new StringBuilder();
        EntryLines.header(text, new Header(EntryLines.VERSION, "0.1.0-test", "2026-11-25T14:30:00.123Z",
                "ObstaclePropagationModel", settings));
        entries.forEach(entry -> EntryLines.write(text, entry));
        if (endMillis >= 0) {
            EntryLines.write(text, new Entry.End(endMillis));
        }
        return text.toString();
    }

    /** Writes {@link #text} with its end into {@code file}. */
    public Path write(Path file, long endMillis) throws IOException {
        return Files.writeString(file, text(endMillis), StandardCharsets.UTF_8);
    }
}
