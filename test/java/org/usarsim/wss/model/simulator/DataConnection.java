package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.usarsim.wss.hub.Sockets.readExactly;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import org.usarsim.wss.hub.TestRobot;

/** A data connection from a robot through a WSS port to the target's accepting socket. */
public record DataConnection(Socket source, Socket target) implements AutoCloseable {

    public static DataConnection open(TestRobot from, int wssPort, ServerSocket targetAccepts) throws IOException {
        Socket source = from.connect(wssPort);
        Socket target = targetAccepts.accept();
        target.setSoTimeout(TestRobot.TIMEOUT_MS);
        return new DataConnection(source, target);
    }

    /** Bytes pass both ways. */
    public void assertPasses(String when) throws IOException {
        source.getOutputStream().write(("ping " + when).getBytes(StandardCharsets.UTF_8));
        assertEquals("ping " + when, readExactly(target.getInputStream(), ("ping " + when).length()), when);
        target.getOutputStream().write(("pong " + when).getBytes(StandardCharsets.UTF_8));
        assertEquals("pong " + when, readExactly(source.getInputStream(), ("pong " + when).length()), when);
    }

    @Override
    public void close() throws IOException {
        source.close();
        target.close();
    }
}
