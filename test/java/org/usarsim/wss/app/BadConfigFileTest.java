package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A properties file with every kind of bad value: each gets one clear line naming the file, the key
 * and the value, and the server exits 2 before anything listens (docs/headless.md).
 */
class BadConfigFileTest {

    @TempDir
    Path dir;

    private Path file(byte[] content) throws IOException {
        Path file = dir.resolve("bad.properties");
        Files.write(file, content);
        return file;
    }

    private Path file(String content) throws IOException {
        return file(content.getBytes(StandardCharsets.UTF_8));
    }

    /** The one-line error for the file; it names the file. */
    private static String error(Path file) {
        String message = assertThrows(ConfigFileException.class, () -> ConfigFile.load(file)).getMessage();
        assertFalse(message.contains("\n"), "one line: " + message);
        assertTrue(message.contains(file.toString()), "names the file: " + message);
        return message;
    }

    /** Every key, each with a value of the wrong type, out of its range, and empty. */
    @ParameterizedTest(name = "{0} = ''{1}''")
    @CsvSource(delimiter = '|', value = {
        "wss.port|abc", "wss.port|65536", "wss.port|-1", "wss.port|5e4", "wss.port|''",
        "wss.bindAddress|''", "wss.bindAddress|'   '",
        "wss.model|''",
        "wss.eventLog|yes", "wss.eventLog|''",
        "wss.eventLogDir|''",
        "wss.matchSourceAddress|on", "wss.matchSourceAddress|''",
        "wss.chunkSize|big", "wss.chunkSize|0", "wss.chunkSize|1048577", "wss.chunkSize|''",
        "wss.socketBuffer|4MB", "wss.socketBuffer|-1", "wss.socketBuffer|268435457", "wss.socketBuffer|''",
        "wss.pluginDir|/no/such/folder",
        "wss.logLevel|DEBUG", "wss.logLevel|info", "wss.logLevel|''",
        "wss.operators|localhost", "wss.operators|127.0.0.1,", "wss.operators|256.0.0.1", "wss.operators|127.0.0.1 127.0.0.2",
        "wss.operators|0.0.0.0", "wss.operators|::", "wss.operators|127.0.0.1, 0:0:0:0:0:0:0:0",
        "wss.force.down|R1", "wss.force.down|R1:R1", "wss.force.down|R1:R2,", "wss.force.down|R1:R2:R3", "wss.force.down|R 1:R2",
        "wss.force.up|:R2", "wss.force.up|R1;R2", "wss.force.up|R1:{R2}", "wss.force.up|R1:R2:fast", "wss.force.up|R1:R2:1M:-5",
        "wss.force.up|R1:R2:1M:50:9:1", "wss.force.up|R1:R2:1M:50:10001", "wss.force.up|R1:R2:::x",
        "wss.shaping.jitter|-1", "wss.shaping.jitter|10001", "wss.shaping.jitterDistribution|gaussian", "wss.shaping.reorder|yes",
        "wss.seed|x",
        "wss.shaping|yes", "wss.shaping|''", "wss.shaping.delayMs|-1", "wss.shaping.delayMs|10001", "wss.shaping.delayMs|2ms",
        "wss.shaping.airtime|yes", "wss.shaping.rates|-74:48M,-72:54M", "wss.shaping.rates|''", "wss.shaping.rates|-72:fast",
        "wss.shaping.rates|-72:0", "wss.shaping.rates|-72:-1M", "wss.shaping.rates|x:54M",
        "usarsim.host|''", "usarsim.host|my host",
        "usarsim.port|seven", "usarsim.port|0", "usarsim.port|65536", "usarsim.port|''",
        "usarsim.interval|1s", "usarsim.interval|99", "usarsim.interval|60001", "usarsim.interval|''",
        "usarsim.timeout|2s", "usarsim.timeout|0", "usarsim.timeout|60001", "usarsim.timeout|''",
        "distance.cutoff|low", "distance.cutoff|NaN", "distance.cutoff|''",
        "distance.pd0|-49,67", "distance.pd0|-Infinity", "distance.pd0|''",
        "distance.n|two", "distance.n|0", "distance.n|-1", "distance.n|''",
        "distance.d0|2m", "distance.d0|0", "distance.d0|''",
        "distance.margin|some", "distance.margin|-0.1", "distance.margin|''",
        "distance.holdTime|1s", "distance.holdTime|-1", "distance.holdTime|''",
        "obstacle.attenuation|six", "obstacle.attenuation|-1", "obstacle.attenuation|''",
        "obstacle.cacheDistance|one", "obstacle.cacheDistance|-0.5", "obstacle.cacheDistance|''",
    })
    void eachBadValueOfEachKeyIsOneLineNamingKeyAndValue(String key, String value) throws Exception {
        String message = error(file("wss.port=0\n" + key + "=" + value + "\n"));
        assertTrue(message.contains(key + " = '" + value.strip() + "' is not "), "names the key, the value and what it should be: " + message);
    }

    @Test
    void aRecordingThatIsAFolderOrNoFileNameIsRefused() throws Exception {
        String folder = error(file("wss.record=" + dir.toString().replace("\\", "\\\\") + "\n"));
        assertTrue(folder.contains("wss.record = '" + dir + "' is not a file to record to: it is a folder"), folder);
        String nul = error(file("wss.record=run\\u0000.rec\n"));
        assertTrue(nul.contains("wss.record = 'run\\u0000.rec' is not a file path"), nul);
    }

    @Test
    void anUnknownKeyNamesItAndTheKnownKeys() throws Exception {
        String message = error(file("wss.prot=5000\n"));
        assertTrue(message.contains("unknown key wss.prot (value '5000')"), message);
        assertTrue(message.contains("known keys: wss.port"), message);
    }

    @Test
    void aLineWithoutAValueIsAnUnknownKey() throws Exception {
        String message = error(file("this is not a property\n"));
        assertTrue(message.contains("unknown key this"), message);
    }

    @Test
    void aFileThatIsNotUtf8SaysSo() throws Exception {
        byte[] latin1 = "usarsim.host=h\u00f6st\n".getBytes(StandardCharsets.ISO_8859_1);
        String message = error(file(latin1));
        assertTrue(message.contains("not UTF-8"), message);
    }

    @Test
    void aMalformedEscapeIsAnError() throws Exception {
        String message = error(file("usarsim.host=\\uZZZZ\n"));
        assertTrue(message.startsWith("cannot read "), message);
    }

    @Test
    void aFolderOrAnAbsentFileCannotBeRead() {
        assertTrue(error(dir).startsWith("cannot read " + dir), "a folder");
        Path absent = dir.resolve("absent.properties");
        assertTrue(error(absent).startsWith("cannot read " + absent), "an absent file");
    }

    /** Through Main.run, as the command line runs it: exit 2, one line on standard error, nothing listened. */
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "usarsim.interval=often|usarsim.interval = 'often'",
        "wss.model=NoSuchModel|wss.model = 'NoSuchModel' is not a known model",
        "ENCODING|not UTF-8",
        "'wss.force.down=A:B\nwss.force.up=B:A'|the pair A:B is in both wss.force.down and wss.force.up",
        "wss.force.down=A:A|is not a comma-separated list of robot pairs A:B",
    })
    void theServerExitsTwoWithOneLine(String content, String expected) throws Exception {
        Path file = content.equals("ENCODING")
                ? file("wss.port=0\nusarsim.host=h\u00f6st\n".getBytes(StandardCharsets.ISO_8859_1))
                : file("wss.bindAddress=127.0.0.1\nwss.port=0\n" + content + "\n");
        MainRun server = MainRun.of("--headless", "--config", file.toString());
        assertEquals(2, server.exitCode(), "exit code; stderr: " + server.stderr());
        String error = server.stderr().strip();
        assertFalse(error.contains("\n"), "one line: " + error);
        assertTrue(error.contains(expected), error);
        assertTrue(server.stdoutLines().stream().noneMatch(line -> line.contains("listening")), server.stdoutLines().toString());
    }
}
