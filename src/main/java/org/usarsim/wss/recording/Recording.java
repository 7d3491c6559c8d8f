package org.usarsim.wss.recording;

import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SortedSet;
import java.util.TreeSet;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;

/**
 * A recording as read (docs/replay.md): its header, its polls in the order of their times, its
 * walls as they changed, every other entry in the order written, and the names of the robots its
 * polls list. What the reader had to skip
 * is said: whether the file was cut short (no {@code end}: a crashed run), how many lines had a
 * keyword this version does not know, how many could not be read.
 */
public record Recording(Header header, List<Entry.Poll> polls, List<Entry.Walls> walls, List<Entry> events,
        SortedSet<String> robots, long durationMillis, boolean cutShort, int unknownLines, int unreadableLines, String firstProblem) {

    public Recording {
        polls = polls instanceof LazyPolls ? polls : List.copyOf(polls);
        walls = List.copyOf(walls);
        events = List.copyOf(events);
        robots = Collections.unmodifiableSortedSet(new TreeSet<>(robots));
    }

    /** The index of the last poll at or before {@code millis}; -1 before the first. */
    public int pollIndexAt(long millis) {
        int low = 0;
        int high = polls.size() - 1;
        int found = -1;
        while (low <= high) {
            int middle = (low + high) >>> 1;
            if (pollMillis(middle) <= millis) {
                found = middle;
                low = middle + 1;
            } else {
                high = middle - 1;
            }
        }
        return found;
    }

    /** The poll's time (without reading its rows). */
    public long pollMillis(int index) {
        return polls instanceof LazyPolls lazy ? lazy.millis(index) : polls.get(index).millis();
    }

    /**
     * Each pair's last row at or before the poll at {@code index}: the state it was last recorded
     * in (a pair of robots that left the recorded run keeps theirs). A pair no poll up to there
     * has is left out. Reads the polls back from {@code index}, only as far as the oldest found.
     */
    public Map<RobotPair, ModelPoll.Pair> lastRows(int index, Set<RobotPair> pairs) {
        Map<RobotPair, ModelPoll.Pair> found = new HashMap<>();
        Set<RobotPair> wanted = new HashSet<>(pairs);
        for (int i = index; i >= 0 && !wanted.isEmpty(); i--) {
            for (ModelPoll.Pair row : polls.get(i).pairs()) {
                RobotPair pair = RobotPair.of(row.first(), row.second());
                if (wanted.remove(pair)) {
                    found.put(pair, row);
                }
            }
        }
        return found;
    }

    /** The walls known at {@code millis}: the last set given at or before it; none before the first. */
    public List<Wall> wallsAt(long millis) {
        List<Wall> known = List.of();
        for (Entry.Walls set : walls) {
            if (set.millis() > millis) {
                break;
            }
            known = set.walls();
        }
        return known;
    }
}
