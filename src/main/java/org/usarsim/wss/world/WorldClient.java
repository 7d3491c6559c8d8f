package org.usarsim.wss.world;

import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.protocol.LineSplitter;

/**
 * One client of the world server, on its own thread: reads lines (CR LF or LF) and writes the
 * answer to each in one write, in order. A line with no answer is only logged. A line over
 * {@link LineSplitter#MAX_LINE_BYTES} drops the client. Its log lines go through the server's
 * {@link WorldServer#lines} limit.
 */
final class WorldClient extends ClientThread implements LineSplitter.Sink {

    private static final Logger LOG = Logger.getLogger(WorldClient.class.getName());

    private final WorldServer server;
    private final LineSplitter splitter = new LineSplitter();

    WorldClient(WorldServer server, Socket socket) {
        super(socket, "world-client");
        this.server = server;
    }

    @Override
    public void run() {
        server.lines().log(LOG, Level.INFO, "clients connected", socket.getInetAddress(), "client " + peer + " connected", null);
        try {
            socket.setTcpNoDelay(true);
            InputStream in = socket.getInputStream();
            byte[] buffer = new byte[16 * 1024];
            int read;
            while (!socket.isClosed() && (read = in.read(buffer)) >= 0) {
                splitter.feed(buffer, 0, read, this);
            }
        } catch (IOException e) {
            LOG.fine(() -> "client " + peer + ": " + e);
        } finally {
            close();
            server.lines().log(LOG, Level.INFO, "clients left", socket.getInetAddress(), "client " + peer + " left", null);
            server.ended(this);
        }
    }

    @Override
    public void line(String line) {
        if (socket.isClosed()) {
            return;
        }
        String reply = PositionProtocol.answer(line, server::now);
        if (reply == null) {
            LOG.fine(() -> "client " + peer + ": no answer to '" + shortened(line) + "'");
            return;
        }
        try {
            socket.getOutputStream().write((reply + "\r\n").getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            LOG.fine(() -> "client " + peer + ": cannot write: " + e);
            close();
        }
    }

    @Override
    public void lineTooLong() {
        server.lines().log(LOG, Level.WARNING, "over-long lines", socket.getInetAddress(),
                "client " + peer + " sent a line over " + LineSplitter.MAX_LINE_BYTES + " bytes: dropping it", null);
        close();
    }

    private static String shortened(String line) {
        return line.length() <= 200 ? line : line.substring(0, 200) + "...";
    }
}
