package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.protocol.Replies;

/**
 * A robot killed in the middle of its transfers: every socket it has (its control connection,
 * a stream it sends, a stream it receives) reset at once, as a crashed process's are. Its links
 * end, both of its peers see their stream end, it is deregistered, and a transfer between two
 * other robots that runs across the kill arrives whole.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RobotResetTest {

    private static final int BLOCK = 16 * 1024;

    private final TestHub server;
    private final List<AutoCloseable> toClose = new ArrayList<>();
    private final ExecutorService pool = Executors.newCachedThreadPool();

    RobotResetTest() throws Exception {
        server = new TestHub();
    }

    @AfterEach
    void stop() throws Exception {
        for (AutoCloseable closeable : toClose) {
            closeable.close();
        }
        server.close();
        pool.shutdownNow();
        assertTrue(pool.awaitTermination(10, TimeUnit.SECONDS));
    }

    @Test
    void aRobotResetMidTransferEndsItsLinksItsPeersSeeItAndNobodyElseIsDisturbed() throws Exception {
        TestRobot a = robot("127.0.0.10");
        TestRobot b = robot("127.0.0.11");
        TestRobot c = robot("127.0.0.12");
        TestRobot d = robot("127.0.0.13");
        TestRobot e = robot("127.0.0.14");
        ServerSocket aAccepts = a.initAccepting("A");
        ServerSocket bAccepts = b.initAccepting("B");
        c.init("C");
        d.init("D");
        ServerSocket eAccepts = e.initAccepting("E");

        // A -> B and C -> A run until A dies; D -> E runs across A's death.
        Socket aToB = open(a.connect(a.dns("B", 0)));
        Socket atB = open(bAccepts.accept());
        Socket cToA = open(c.connect(c.dns("A", 0)));
        Socket atA = open(aAccepts.accept());
        Socket dToE = open(d.connect(d.dns("E", 0)));
        Socket atE = open(eAccepts.accept());
        AtomicLong bReceived = new AtomicLong();
        AtomicLong aReceived = new AtomicLong();
        AtomicLong eReceived = new AtomicLong();
        pool.submit(() -> writeUntilBroken(aToB));
        pool.submit(() -> writeUntilBroken(cToA));
        Future<String> bSaw = pool.submit(() -> readToTheEnd(atB, bReceived));
        Future<String> aSaw = pool.submit(() -> readToTheEnd(atA, aReceived));
        Future<String> cSaw = pool.submit(() -> readToTheEnd(cToA, new AtomicLong()));
        MessageDigest sent = MessageDigest.getInstance("SHA-256");
        MessageDigest arrived = MessageDigest.getInstance("SHA-256");
        Future<String> eSaw = pool.submit(() -> readToTheEnd(atE, eReceived, arrived));
        Random random = new Random(42);
        byte[] block = new byte[BLOCK];
        long dSent = 0;
        OutputStream dOut = dToE.getOutputStream();
        while (bReceived.get() < 256 * 1024 || aReceived.get() < 256 * 1024 || eReceived.get() < 256 * 1024) {
            dSent += writeBlock(dOut, random, block, sent);
        }

        kill(a.control, aToB, atA);
        aAccepts.close();

        assertSeesTheEnd(bSaw, "B, receiving from A");
        assertSeesTheEnd(cSaw, "C, sending to A");
        aSaw.get(10, TimeUnit.SECONDS);
        cToA.close();
        atB.close();
        Wait.until("A's links ended", () -> linkThreadsOf("A") == 0);
        Wait.until("A is deregistered", () -> !server.hub.getListOfRegisteredRobots().contains("A"));
        assertEquals(Replies.signalUnknownRobot("A"), b.ask("GETSS {Robot A}"));
        assertEquals(Replies.dnsNoSuchRobot("A"), c.ask("DNS {Robot A}"));

        // Nobody else is disturbed: D's stream goes on, and arrives whole.
        assertEquals(1, linkThreadsOf("D"), "D -> E still forwarded");
        for (int i = 0; i < 64; i++) {
            dSent += writeBlock(dOut, random, block, sent);
        }
        dToE.shutdownOutput();
        assertEquals("ended", eSaw.get(10, TimeUnit.SECONDS));
        assertEquals(dSent, eReceived.get(), "bytes D sent, E received");
        assertEquals(HexFormat.of().formatHex(sent.digest()), HexFormat.of().formatHex(arrived.digest()), "SHA-256 of D -> E");
        assertEquals(Replies.signal("C", 0), b.ask("GETSS {Robot C}"));
        assertEquals(Replies.signal("E", 0), d.ask("GETSS {Robot E}"));
    }

    /** The stream ended (end of stream, or a reset: both say the other robot is gone), well before the read timeout. */
    private static void assertSeesTheEnd(Future<String> reader, String who) throws Exception {
        String how = reader.get(10, TimeUnit.SECONDS);
        System.out.println("robot reset: " + who + " saw: " + how);
        assertTrue(how.equals("ended") || how.startsWith("reset"), who + ": " + how);
    }

    private TestRobot robot(String address) throws Exception {
        TestRobot robot = server.robotAt(address);
        toClose.add(robot);
        return robot;
    }

    private Socket open(Socket socket) throws IOException {
        toClose.add(socket);
        socket.setSoTimeout(TestRobot.TIMEOUT_MS);
        return socket;
    }

    /** Resets every socket at once, as the OS does for a process that dies with unread data. */
    private static void kill(Socket... sockets) throws IOException {
        for (Socket socket : sockets) {
            socket.setSoLinger(true, 0);
            socket.close();
        }
    }

    private static int writeBlock(OutputStream out, Random random, byte[] block, MessageDigest digest) throws IOException {
        random.nextBytes(block);
        out.write(block);
        digest.update(block);
        return block.length;
    }

    private static Void writeUntilBroken(Socket socket) {
        byte[] block = new byte[BLOCK];
        try {
            OutputStream out = socket.getOutputStream();
            while (true) {
                out.write(block);
            }
        } catch (IOException broken) {
            return null;
        }
    }

    private static String readToTheEnd(Socket socket, AtomicLong count) {
        return readToTheEnd(socket, count, null);
    }

    /** Reads until end of stream ("ended") or a reset ("reset: ..."); a read timeout is a failure. */
    private static String readToTheEnd(Socket socket, AtomicLong count, MessageDigest digest) {
        byte[] block = new byte[BLOCK];
        try {
            InputStream in = socket.getInputStream();
            int read;
            while ((read = in.read(block)) >= 0) {
                if (digest != null) {
                    digest.update(block, 0, read);
                }
                count.addAndGet(read);
            }
            return "ended";
        } catch (SocketException e) {
            return "reset: " + e.getMessage();
        } catch (IOException e) {
            return "failed: " + e;
        }
    }

    /** The server's link threads with this robot at either end. */
    private static long linkThreadsOf(String robot) {
        return Thread.getAllStackTraces().keySet().stream().map(Thread::getName)
                .filter(n -> n.startsWith("link " + robot + " -> ") || n.matches("link \\S+ -> " + robot + ":\\d+")).count();
    }
}
