package org.usarsim.wss.monitor;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.routes.RouteTable;

/**
 * For a benchmark (bench.RouteBenchmark): the bytes of the monitor's route events a stream is told
 * as the route table changes, by the monitor's own rule ({@link StateDiff}: with the counts once a
 * second, at once when a robot is cut off or back; the routes that changed, or the whole when
 * shorter), and the bytes the whole table would be at every change.
 */
public final class RouteEventSizes {

    private static final long SECOND = 1_000_000_000;
    private final StateDiff diff = new StateDiff();
    private RouteTable last = RouteTable.EMPTY;
    private long lastCountsNs = Long.MIN_VALUE;
    private long told;
    private long events;
    private long whole;
    private long changes;

    /** The table at {@code nowNs}. */
    public void next(RouteTable table, long nowNs) {
        boolean countsDue = lastCountsNs == Long.MIN_VALUE || nowNs - lastCountsNs >= SECOND;
        if (countsDue) {
            lastCountsNs = nowNs;
        }
        RoutesJson routes = RoutesJson.of(table);
        if (!table.equals(last)) {
            whole += bytes(routes.json());
            changes++;
            last = table;
        }
        for (StateDiff.Change change : diff.step(new Reading(List.of(), List.of(), List.of(), List.of(), List.of(), null, null, routes),
                countsDue)) {
            told += bytes(change.data());
            events++;
        }
    }

    private static long bytes(Object json) {
        return Json.write(json).getBytes(StandardCharsets.UTF_8).length;
    }

    /** The bytes of the route events a stream was told, in all. */
    public long told() {
        return told;
    }

    /** The route events a stream was told. */
    public long events() {
        return events;
    }

    /** The bytes of the whole table at every change, in all. */
    public long whole() {
        return whole;
    }

    /** The changes of the table. */
    public long changes() {
        return changes;
    }
}
