package org.usarsim.wss.model.rfcomms;

import org.usarsim.wss.model.simulator.PollClock;

/**
 * The RFComms model with the DARPA SubT simulator's comms settings (osrf/subt's worlds:
 * tx_power 20 dBm, capacity 1 Mbit/s, max_range 500 m, the rest as RFComms). SubT's visibility
 * cost, which raises the fading exponent by 0.2 per unit along its tunnels' graph, is not
 * modelled (docs/models.md says how to approach it with the exponent).
 */
public final class SubtPropagationModel extends RfCommsPropagationModel {

    public SubtPropagationModel() {
        this(PollClock.SYSTEM);
    }

    /** The poller takes its time from {@code clock}. */
    public SubtPropagationModel(PollClock clock) {
        super(RfChannel.SUBT, clock);
    }

    @Override
    public String name() {
        return "SubT";
    }
}
