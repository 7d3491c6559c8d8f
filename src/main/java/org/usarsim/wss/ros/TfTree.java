package org.usarsim.wss.ros;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

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
    /** Each parent frame's children, so that a message's frames find the frames below them. */
    private final Map<String, Set<String>> children = new HashMap<>();

    TfTree(String root) {
        this.root = plain(root);
    }

    /**
     * Takes one message's transforms (child frame to link), then gives the pose in the root frame
     * of every frame whose chain to the root changed (a frame of the message or a frame below
     * one), each with its own link's stamp; frames with no chain to the root (yet), and frames
     * whose pose adds up to more than a double holds, are left out.
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
        for (Map.Entry<String, Link> entry : message.entrySet()) {
            Link old = links.put(entry.getKey(), entry.getValue());
            if (old != null && !old.parent().equals(entry.getValue().parent())) {
                Set<String> siblings = children.get(old.parent());
                siblings.remove(entry.getKey());
                if (siblings.isEmpty()) {
                    children.remove(old.parent());
                }
            }
            children.computeIfAbsent(entry.getValue().parent(), parent -> new LinkedHashSet<>()).add(entry.getKey());
        }
        List<RobotPose> poses = new ArrayList<>();
        for (String frame : below(message.keySet())) {
            if (frame.equals(root)) {
                continue;
            }
            Transform pose = toRoot(frame);
            // A chain of huge translations can add up to infinity: that frame is left out, as one with no chain.
            if (pose != null && Double.isFinite(pose.x()) && Double.isFinite(pose.y()) && Double.isFinite(pose.z())) {
                poses.add(new RobotPose(frame, pose.x(), pose.y(), pose.z(), links.get(frame).stampNanos()));
            }
        }
        return poses;
    }

    /** The frames given and every frame below one of them, each once (a loop ends where it began). */
    private Set<String> below(Set<String> frames) {
        Set<String> found = new LinkedHashSet<>(frames);
        Deque<String> next = new ArrayDeque<>(frames);
        while (!next.isEmpty()) {
            for (String child : children.getOrDefault(next.poll(), Set.of())) {
                if (found.add(child)) {
                    next.add(child);
                }
            }
        }
        return found;
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
