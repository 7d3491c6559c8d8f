package org.usarsim.wss.app;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingException;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.recording.WorldExport;

/**
 * {@code --export-world RUN.rec [--out FILE]}: the recording as a world file (docs/replay.md), to
 * standard output or to the file. A recording cut short, or with lines skipped, is exported all
 * the same, with a warning on standard error; one with no poll (no robot's position) is refused.
 */
final class WorldFileExport {

    private WorldFileExport() {
    }

    /**
     * Writes the world file: {@link Main#OK}; a recording that cannot be read or holds no poll (refused
     * as the replay refuses it), or a file that cannot be written, is bad input.
     */
    static int run(PrintStream out, PrintStream err, Options.ExportWorld options) throws RunFailure {
        Path recordingFile = options.recording();
        Path to = options.out();
        Recording recording;
        try {
            recording = RecordingReader.readPolled(recordingFile);
        } catch (RecordingException e) {
            throw RunFailure.badInput(e.getMessage());
        }
        if (recording.cutShort()) {
            err.println("wss: warning: " + recordingFile + " was cut short (no end line): exported up to its last whole line");
        }
        if (recording.unknownLines() + recording.unreadableLines() > 0) {
            err.println("wss: warning: " + recordingFile + ": skipped " + recording.unknownLines() + " unknown and "
                    + recording.unreadableLines() + " unreadable lines (the first: " + recording.firstProblem() + ")");
        }
        String text = WorldExport.worldFile(recording, recordingFile.getFileName().toString());
        if (to == null) {
            out.print(text);
            out.flush();
            return Main.OK;
        }
        try {
            Files.writeString(to, text, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw RunFailure.badInput("cannot write the world file " + to + ": its folder " + to.toAbsolutePath().getParent()
                    + " does not exist");
        } catch (AccessDeniedException e) {
            throw RunFailure.badInput("cannot write the world file " + to + ": permission denied");
        } catch (IOException e) {
            throw RunFailure.badInput("cannot write the world file " + to + ": " + (e.getMessage() == null ? e.toString() : e.getMessage()));
        }
        return Main.OK;
    }
}
