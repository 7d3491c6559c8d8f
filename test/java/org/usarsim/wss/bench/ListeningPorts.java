package org.usarsim.wss.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/** The TCP port numbers that have a listening socket in this network namespace now (/proc/net/tcp and tcp6, state 0A). */
final class ListeningPorts {

    private ListeningPorts() {
    }

    static Set<Integer> now() throws IOException {
        Set<Integer> listening = new HashSet<>();
        for (String table : List.of("/proc/net/tcp", "/proc/net/tcp6")) {
            for (String line : Files.readAllLines(Path.of(table))) {
                String[] fields = line.trim().split("\\s+");
                if (fields.length > 3 && fields[3].equals("0A")) {
                    String local = fields[1];
                    listening.add(Integer.parseInt(local.substring(local.lastIndexOf(':') + 1), 16));
                }
            }
        }
        return listening;
    }
}
