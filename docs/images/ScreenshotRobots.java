import java.io.IOException;
import java.io.InputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The three robots of docs/images/main-window.png (docs/gui.md, "For developers"): Base, Scout and
 * Relay register with the WSS on 127.0.0.1:50000, each accepting on a port of its own, ask a WSS
 * port for every pair, and connect through each but Scout -> Base; then they wait SECONDS.
 * With {@code traffic} (docs/images/link-statistics.png) they connect through every pair, the
 * WSS on PORT, and each connection carries data both ways: its source sends a chunk ten times a
 * second, its target answers a tenth of what it reads.
 *
 *     java docs/images/ScreenshotRobots.java SECONDS [PORT traffic]
 */
public class ScreenshotRobots {

    private static final Map<String, Socket> CONTROL = new LinkedHashMap<>();
    private static final List<Socket> KEPT = new ArrayList<>();

    private static String ask(String robot, String command) throws IOException {
        Socket socket = CONTROL.get(robot);
        socket.getOutputStream().write((command + "\r\n").getBytes(StandardCharsets.UTF_8));
        StringBuilder line = new StringBuilder();
        InputStream in = socket.getInputStream();
        for (int c = in.read(); c != '\n' && c >= 0; c = in.read()) {
            if (c != '\r') {
                line.append((char) c);
            }
        }
        return line.toString();
    }

    public static void main(String[] args) throws Exception {
        int wssPort = args.length > 1 ? Integer.parseInt(args[1]) : 50000;
        boolean traffic = args.length > 2 && args[2].equals("traffic");
        for (String name : List.of("Base", "Scout", "Relay")) {
            ServerSocket accepts = new ServerSocket(0);
            Thread acceptor = new Thread(() -> {
                while (true) {
                    try {
                        Socket accepted = accepts.accept();
                        synchronized (KEPT) {
                            KEPT.add(accepted);
                        }
                        if (traffic) {
                            daemon(() -> answer(accepted));
                        }
                    } catch (IOException e) {
                        return;
                    }
                }
            });
            acceptor.setDaemon(true);
            acceptor.start();
            CONTROL.put(name, new Socket("127.0.0.1", wssPort));
            System.out.println(name + ": " + ask(name, "INIT {Robot " + name + "} {Port " + accepts.getLocalPort() + "}"));
        }
        String[][] pairs = {{"Base", "Relay"}, {"Relay", "Base"}, {"Relay", "Scout"}, {"Scout", "Relay"}, {"Base", "Scout"}, {"Scout", "Base"}};
        for (String[] pair : pairs) {
            String reply = ask(pair[0], "DNS {Robot " + pair[1] + "}");
            System.out.println(pair[0] + " -> " + pair[1] + ": " + reply);
            int port = Integer.parseInt(reply.replaceAll(".*\\{Port (-?\\d+)\\}.*", "$1"));
            if (traffic) {
                try {
                    Socket data = new Socket("127.0.0.1", port);
                    int chunk = 2000 * (KEPT.size() + 1);
                    daemon(() -> send(data, chunk));
                    daemon(() -> drain(data));
                } catch (IOException e) {
                    System.out.println(pair[0] + " -> " + pair[1] + ": " + e.getMessage()); // out of range now
                }
            } else if (!(pair[0].equals("Scout") && pair[1].equals("Base"))) {
                Socket data = new Socket("127.0.0.1", port);
                synchronized (KEPT) {
                    KEPT.add(data);
                }
            }
        }
        Thread.sleep(Long.parseLong(args[0]) * 1000);
    }

    private interface Work {
        void run() throws Exception;
    }

    private static void daemon(Work work) {
        Thread thread = new Thread(() -> {
            try {
                work.run();
            } catch (Exception e) {
                // the connection closed
            }
        });
        thread.setDaemon(true);
        thread.start();
    }

    private static void send(Socket data, int chunk) throws Exception {
        while (true) {
            data.getOutputStream().write(new byte[chunk]);
            Thread.sleep(100);
        }
    }

    private static void answer(Socket accepted) throws IOException {
        byte[] buffer = new byte[65536];
        for (int n; (n = accepted.getInputStream().read(buffer)) > 0;) {
            accepted.getOutputStream().write(buffer, 0, Math.max(1, n / 10));
        }
    }

    private static void drain(Socket data) throws IOException {
        data.getInputStream().transferTo(java.io.OutputStream.nullOutputStream());
    }
}
