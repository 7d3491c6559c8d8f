package org.usarsim.wss.attach;

import java.util.function.BiConsumer;
import org.usarsim.wss.Decimals;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonNode;

/**
 * The replay of an attached server as the time bar uses it: where it is, as the last {@code replay}
 * event said, and its controls sent as POST /api/replay (on the client's command thread; the bar
 * shows the change at once, the server's next event confirms it). Read on the event thread,
 * followed on the client's.
 */
final class RemoteReplay implements Replay {

    private final BiConsumer<String, String> post;
    private volatile boolean running;
    private volatile double duration;
    private volatile double time;
    private volatile double poll;
    private volatile double speed = 1;
    private volatile boolean playing;

    RemoteReplay(BiConsumer<String, String> post) {
        this.post = post;
    }

    /** The replay object of the state (null: none runs). */
    void follow(JsonNode replay) throws JsonException {
        running = replay != null;
        if (replay != null) {
            duration = replay.get("durationSeconds").number();
            time = replay.get("timeSeconds").number();
            speed = replay.get("speed").number();
            playing = replay.get("playing").bool();
            JsonNode polled = replay.optional("pollSeconds");
            poll = polled == null || polled.isNull() ? time : polled.number();
        }
    }

    boolean running() {
        return running;
    }

    @Override
    public double durationSeconds() {
        return duration;
    }

    @Override
    public double timeSeconds() {
        return time;
    }

    @Override
    public double pollSeconds() {
        return poll;
    }

    @Override
    public double speed() {
        return speed;
    }

    @Override
    public boolean playing() {
        return playing;
    }

    @Override
    public void play() {
        playing = true;
        post.accept("/api/replay", "{State Play}");
    }

    @Override
    public void pause() {
        playing = false;
        post.accept("/api/replay", "{State Pause}");
    }

    @Override
    public void speed(double times) {
        speed = times;
        post.accept("/api/replay", "{Speed " + Decimals.plain(times) + "}");
    }

    @Override
    public void jump(double seconds) {
        time = seconds;
        post.accept("/api/replay", "{Time " + Decimals.plain(seconds) + "}");
    }
}
