package org.usarsim.wss.replay;

import java.util.List;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.Wall;

/**
 * A run of the replay as its controls and the map see it: the {@link ReplayPlayer} from a start to
 * its shutdown, or {@link #STOPPED}.
 */
interface ReplayRun extends Replay {

    /** No replay: nothing to play, its time 0, at speed 1; the controls do nothing. */
    ReplayRun STOPPED = new ReplayRun() {
        @Override
        public double durationSeconds() {
            return 0;
        }

        @Override
        public double pollSeconds() {
            return 0;
        }

        @Override
        public double timeSeconds() {
            return 0;
        }

        @Override
        public double speed() {
            return 1;
        }

        @Override
        public boolean playing() {
            return false;
        }

        @Override
        public void play() {
        }

        @Override
        public void pause() {
        }

        @Override
        public void speed(double times) {
        }

        @Override
        public void jump(double seconds) {
        }

        @Override
        public List<Wall> walls() {
            return List.of();
        }

        @Override
        public void stop() {
        }
    };

    /** The walls recorded at or before the replay's time. */
    List<Wall> walls();

    /** Stops the run's thread. */
    void stop();
}
