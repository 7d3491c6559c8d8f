package org.usarsim.wss.hub;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.LocalTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.logging.Logger;
import java.util.stream.Collectors;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.protocol.Strengths;

/**
 * The original's "Enable Logging" file: one CSV line per event in
 * {@code log-yyyy.MM.dd-HH.mm.ss.SSS.txt}, with the time of day as {@code HH:mm:ss.SSS}.
 * Every line but DATA_SENT is flushed at once; DATA_SENT lines (one per chunk) are flushed with
 * the next other event, when the buffer fills, or at close.
 */
public final class CsvEventLog implements WssEventListener, AutoCloseable {

    private static final Logger LOG = Logger.getLogger(CsvEventLog.class.getName());
    private static final DateTimeFormatter FILE_TIME = DateTimeFormatter.ofPattern("yyyy.MM.dd-HH.mm.ss.SSS");
    private static final DateTimeFormatter LINE_TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");

    private final Path file;
    private final Writer out;
    private boolean failed;

    private CsvEventLog(Path file, Writer out) {
        this.file = file;
        this.out = out;
    }

    /** Creates a new log file in the directory (created if missing), named by the time now. */
    public static CsvEventLog create(Path directory) throws IOException {
        Files.createDirectories(directory);
        Path file = directory.resolve("log-" + FILE_TIME.format(LocalDateTime.now()) + ".txt");
        BufferedWriter out = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        LOG.info("writing the event log to " + file.toAbsolutePath());
        return new CsvEventLog(file, out);
    }

    public Path file() {
        return file;
    }

    private synchronized void write(String type, boolean flush, Object... fields) {
        if (failed) {
            return;
        }
        StringBuilder line = new StringBuilder(64).append(type).append(',').append(LINE_TIME.format(LocalTime.now()));
        for (Object field : fields) {
            line.append(',').append(field);
        }
        try {
            out.write(line.append(System.lineSeparator()).toString());
            if (flush) {
                out.flush();
            }
        } catch (IOException e) {
            failed = true;
            LOG.warning("the event log " + file + " cannot be written any more: " + e.getMessage());
        }
    }

    @Override
    public void robotRegistered(String robot, String address, List<Integer> ports) {
        write("REGISTERED", true, robot, address, ports.stream().map(String::valueOf).collect(Collectors.joining(":")));
    }

    @Override
    public void robotDeregistered(String robot) {
        write("DEREGISTERED", true, robot);
    }

    @Override
    public void robotOutOfBattery(String robot) {
        write("OUT_OF_BATTERY", true, robot);
    }

    @Override
    public void connectionOutOfRange(String from, String to, double strength, double distance) {
        write("OUT_OF_RANGE", true, from, to, Strengths.format(strength), Strengths.format(distance));
    }

    @Override
    public void connectionInRange(String from, String to) {
        write("IN_RANGE", true, from, to);
    }

    @Override
    public void connectionEstablished(String from, String to, int targetPort) {
        write("CON_ESTABLISHED", true, from, to, targetPort);
    }

    @Override
    public void connectionTerminated(String from, String to, int targetPort) {
        write("CON_TERMINATED", true, from, to, targetPort);
    }

    @Override
    public void dataSent(String from, String to, int bytes) {
        write("DATA_SENT", false, from, to, bytes);
    }

    @Override
    public synchronized void close() {
        try {
            out.close();
        } catch (IOException e) {
            LOG.warning("closing the event log " + file + ": " + e.getMessage());
        }
    }
}
