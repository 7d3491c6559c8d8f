package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

/** What the socket tests do with the bytes and ends of a connection. */
public final class Sockets {

    private Sockets() {
    }

    /** A TCP port number free on 127.0.0.1 now, for a port a test configures (a fixed port, a control port). */
    public static int freeTcp() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return socket.getLocalPort();
        }
    }

    /** A UDP port number free on 127.0.0.1 now, for a fixed UDP port. */
    public static int freeUdp() throws IOException {
        try (DatagramSocket socket = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            return socket.getLocalPort();
        }
    }

    public static byte[] randomBytes(int size, long seed) {
        byte[] data = new byte[size];
        new Random(seed).nextBytes(data);
        return data;
    }

    /**
     * A stream of sequence numbers, for checking order: the bytes from {@code position} on, each
     * 8-byte big-endian number in turn (0, 1, 2 ...).
     */
    public static void sequence(byte[] bytes, long position) {
        for (int i = 0; i < bytes.length; i++) {
            long at = position + i;
            bytes[i] = (byte) ((at / 8) >>> (8 * (7 - at % 8)));
        }
    }

    public static String readExactly(InputStream in, int length) throws IOException {
        return new String(readExactlyBytes(in, length), StandardCharsets.UTF_8);
    }

    public static byte[] readExactlyBytes(InputStream in, int length) throws IOException {
        byte[] data = in.readNBytes(length);
        assertEquals(length, data.length, "bytes before end of stream");
        return data;
    }

    /** Writes the text (a command line with its CR LF, say) and flushes. */
    public static void send(Socket socket, String text) throws IOException {
        OutputStream out = socket.getOutputStream();
        out.write(text.getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    /**
     * One reply line with its line end, read byte by byte up to LF (or what came before end of
     * stream); the socket's timeout bounds the wait.
     */
    public static String readLine(Socket socket) throws IOException {
        InputStream in = socket.getInputStream();
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        int b;
        while ((b = in.read()) != -1) {
            line.write(b);
            if (b == '\n') {
                break;
            }
        }
        return line.toString(StandardCharsets.UTF_8);
    }

    /** The other end closed: the next read is end of stream or a reset, well before the read timeout. */
    public static void assertClosedByPeer(Socket socket, String what) throws IOException {
        socket.setSoTimeout(TestRobot.TIMEOUT_MS);
        int read;
        try {
            read = socket.getInputStream().read();
        } catch (SocketTimeoutException e) {
            fail(what + ": still open after " + TestRobot.TIMEOUT_MS + " ms");
            return;
        } catch (SocketException reset) {
            return;
        }
        assertEquals(-1, read, what + ": end of stream");
    }

    /**
     * Sockets listening on the port number, in this process's network namespace (/proc/net/tcp and
     * tcp6, state 0A): a WSS port that listens has exactly one.
     */
    public static long listeningSockets(int port) {
        String local = String.format(":%04X ", port);
        long count = 0;
        for (String table : List.of("/proc/net/tcp", "/proc/net/tcp6")) {
            try {
                for (String line : Files.readAllLines(Path.of(table))) {
                    String[] fields = line.trim().split("\\s+");
                    if (fields.length > 3 && (fields[1] + " ").endsWith(local) && fields[3].equals("0A")) {
                        count++;
                    }
                }
            } catch (IOException e) {
                throw new AssertionError("cannot read " + table, e);
            }
        }
        return count;
    }

    /** This process's open descriptors. */
    public static long openDescriptors() {
        try (Stream<Path> entries = Files.list(Path.of("/proc/self/fd"))) {
            return entries.count();
        } catch (IOException e) {
            throw new AssertionError("cannot list /proc/self/fd", e);
        }
    }

    /** Closes each, the last opened first, ignoring what is closed already. */
    public static void closeAllNewestFirst(List<? extends AutoCloseable> opened) {
        for (int i = opened.size() - 1; i >= 0; i--) {
            try {
                opened.get(i).close();
            } catch (Exception ignored) {
                // closed already
            }
        }
    }

    /** The server's threads that forward a connection. */
    public static long linkThreads() {
        return Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().startsWith("link ")).count();
    }
}
