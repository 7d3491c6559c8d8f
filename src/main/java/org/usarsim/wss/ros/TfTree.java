package org.usarsim.wss.ros;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The transforms tf has sent so far, each child frame with its parent, kept across messages
 * (tf sends partial trees: {@code /tf_static}'s {@code map -> Scout/odom} once, {@code /tf}'s
 * {@code Scout/odom -> Scout/base_link} at its rate). Frame names are taken without a leading
 * {@code /} (ROS 1's {@code /world} is {@code world}). At most {@link #MAX_FRAMES} frames: the
 * transforms of new frames beyond it are refused. Not thread-safe: one source's thread uses it.
 */
final class TfTree {

    /** The most frames kept: more than any robot team's tree, few enough to bound the memory a bad source takes. */
    static final int MAX_FRAMES = 10_000;

    /** A child frame's transform from its parent, with the stamp it came with. */
    record Link(String parent, Transform transform, long stampNanos) {
    }

    private final String root;
    private final Map<String, Link> links = new HashMap<>();

    TfTree(String root) {
        this.root = plain(root);
    }

    /**
     * Takes one message's transforms (child frame to link), then gives the pose in the root frame
     * of every frame whose chain to the root changed (a frame of the message or a frame below
     * one), each with its own link's stamp; frames with no chain to the root (yet) are left out.
     *
     * @throws JsonException the message would take the tree over {@link #MAX_FRAMES} frames
     */
    List<RobotPose> update(Map<String, Link> message) throws JsonException {
        int added = 0;
        for (String child : message.keySet()) {
            if (!links.containsKey(child)) {
                added++;
            }
        }
        if (links.size() + added > MAX_FRAMES) {
            throw JsonException.in("msg.transforms", "more than " + MAX_FRAMES + " frames in the tf tree: refused");
        }
        links.putAll(message);
        Map<String, Boolean> changed = new HashMap<>();
        List<RobotPose> poses = new ArrayList<>();
        for (Map.Entry<String, Link> entry : links.entrySet()) {
            String frame = entry.getKey();
            if (frame.equals(root) || !changed(frame, message, changed)) {
                continue;
            }
            Transform pose = toRoot(frame);
            if (pose != null) {
                if (!Double.isFinite(pose.x()) || !Double.isFinite(pose.y()) || !Double.isFinite(pose.z())) {
                    throw JsonException.in("msg.transforms", "the pose of " + JsonException.shortened(frame) + " in " + JsonException.shortened(root) + " is not finite");
                }
                poses.add(new RobotPose(frame, pose.x(), pose.y(), pose.z(), entry.getValue().stampNanos()));
            }
        }
        return poses;
    }

    /** Whether the frame or a frame on its chain up is in the message (memoised; a cycle is "not"). */
    private boolean changed(String frame, Map<String, Link> message, Map<String, Boolean> memo) {
        List<String> chain = new ArrayList<>();
        String at = frame;
        boolean result = false;
        while (at != null && !at.equals(root) && chain.size() <= links.size()) {
            Boolean known = memo.get(at);
            if (known != null) {
                result = known;
                break;
            }
            if (message.containsKey(at)) {
                result = true;
                break;
            }
            chain.add(at);
            Link link = links.get(at);
            at = link == null ? null : link.parent();
        }
        for (String f : chain) {
            memo.put(f, result);
        }
        return result;
    }

    /** The frame's pose in the root frame; null when its chain does not reach the root (or loops). */
    private Transform toRoot(String frame) {
        Transform pose = Transform.IDENTITY;
        String at = frame;
        for (int steps = 0; steps <= links.size(); steps++) {
            if (at.equals(root)) {
                return pose;
            }
            Link link = links.get(at);
            if (link == null) {
                return null;
            }
            pose = link.transform().then(pose);
            at = link.parent();
        }
        return null;
    }

    /** The frames kept. */
    int size() {
        return links.size();
    }

    /** A frame's name without a leading {@code /}. */
    static String plain(String frame) {
        return frame.startsWith("/") ? frame.substring(1) : frame;
    }
}
