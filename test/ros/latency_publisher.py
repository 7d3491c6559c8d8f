#!/usr/bin/env python3
"""Publishes robots' poses on a real ROS 1 graph for RosbridgeBenchmark (docs/performance.md,
"Positions over rosbridge"). rospy only; run it with a ROS environment sourced. It stops when its
standard input ends (the benchmark closes it), or on SIGINT / SIGTERM.

--mode place (the latency run): gazebo_msgs/ModelStates on --topic at --rate, with the models
    the benchmark places by writing `place NAME X Y` lines to standard input (and --extra models
    that stand still, as Gazebo's ground_plane does). A place is published at once, out of the
    tick (the tick then starts again from it), and said on standard output as
    `published NAME <time.time_ns() just before the publish>`.
--mode model_states (the CPU run): --robots robots R0 .. R{N-1}, each moving on a circle of
    30 m around its own centre, the same paths as the benchmark's USARSim peer, at --rate.
--mode tf (the CPU run): --publishers nodes of their own, each publishing one
    tf2_msgs/TFMessage with its share of the --robots robots (--frame -> Ri/base_link, stamped
    with the wall clock) at --rate on --topic.

On its end each mode says `sent N messages in S s` on standard output.
"""
import argparse
import math
import os
import signal
import subprocess
import sys
import threading
import time

import rospy


def options(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mode", choices=["place", "model_states", "tf"], default="place")
    parser.add_argument("--rate", type=float, default=5.0, help="messages a second (of each publisher)")
    parser.add_argument("--topic", help="default: /bench/model_states, or /bench/tf in mode tf")
    parser.add_argument("--robots", type=int, default=100, help="model_states and tf: how many robots")
    parser.add_argument("--publishers", type=int, default=10, help="tf: how many nodes publish on the topic")
    parser.add_argument("--frame", default="world", help="tf: the parent frame of every robot")
    parser.add_argument("--extra", type=int, default=1, help="place: models besides the robots placed (ground_plane, ...)")
    parser.add_argument("--index", type=int, default=-1, help=argparse.SUPPRESS)  # tf: this node is publisher INDEX
    result = parser.parse_args(argv)
    if result.topic is None:
        result.topic = "/bench/tf" if result.mode == "tf" else "/bench/model_states"
    if result.rate <= 0 or result.robots < 1 or result.publishers < 1:
        parser.error("--rate, --robots and --publishers must be above 0")
    return result


def circle(i, seconds):
    """Robot i at a time: on a circle of 30 m around its own centre (RosbridgeBenchmark's peer has the same)."""
    angle = seconds * 0.5 + i
    return (i % 10) * 20 + 30 * math.cos(angle), (i // 10) * 20 + 30 * math.sin(angle)


class Ticks:
    """The publishing loop's clock: a tick every 1 / rate, woken early by wake(); done when stdin ends."""

    def __init__(self, rate):
        self.period = 1.0 / rate
        self.woken = threading.Event()
        self.done = threading.Event()
        self.sent = 0
        self.start = time.monotonic()

    def wake(self):
        self.woken.set()

    def run(self, publish_once):
        due = time.monotonic()
        while not self.done.is_set() and not rospy.is_shutdown():
            self.woken.wait(max(0.0, due - time.monotonic()))
            early = self.woken.is_set()
            self.woken.clear()
            if self.done.is_set():
                break
            publish_once()
            self.sent += 1
            now = time.monotonic()
            due = now + self.period if early or due + self.period < now else due + self.period

    def said(self):
        seconds = time.monotonic() - self.start
        print("sent %d messages in %.1f s (%.1f a second)" % (self.sent, seconds, self.sent / max(seconds, 1e-9)), flush=True)


def read_stdin(ticks, on_line=None):
    for line in sys.stdin:
        if on_line is not None:
            on_line(line.split())
    ticks.done.set()
    ticks.wake()


def background(target, *args):
    thread = threading.Thread(target=target, args=args, daemon=True)
    thread.start()


def pose(x, y):
    from geometry_msgs.msg import Point, Pose, Quaternion
    return Pose(position=Point(x, y, 0.0), orientation=Quaternion(0.0, 0.0, 0.0, 1.0))


def model_states(models):
    from gazebo_msgs.msg import ModelStates
    from geometry_msgs.msg import Twist
    return ModelStates(name=list(models), pose=[pose(x, y) for x, y in models.values()], twist=[Twist() for _ in models])


def place_mode(args):
    from gazebo_msgs.msg import ModelStates
    rospy.init_node("bench_place", anonymous=True)
    publisher = rospy.Publisher(args.topic, ModelStates, queue_size=10)
    models = {"ground_plane" if i == 0 else "static_%d" % i: (0.0, 0.0) for i in range(args.extra)}
    placed = []
    lock = threading.Lock()
    ticks = Ticks(args.rate)

    def on_line(words):
        if len(words) == 4 and words[0] == "place":
            with lock:
                models[words[1]] = (float(words[2]), float(words[3]))
                placed.append(words[1])
            ticks.wake()

    def publish_once():
        with lock:
            message = model_states(models)
            said = list(placed)
            placed.clear()
        now = time.time_ns()
        publisher.publish(message)
        for name in said:
            print("published %s %d" % (name, now), flush=True)

    background(read_stdin, ticks, on_line)
    ticks.run(publish_once)
    ticks.said()


def model_states_mode(args):
    from gazebo_msgs.msg import ModelStates
    rospy.init_node("bench_model_states", anonymous=True)
    publisher = rospy.Publisher(args.topic, ModelStates, queue_size=10)
    ticks = Ticks(args.rate)

    def publish_once():
        seconds = time.monotonic() - ticks.start
        publisher.publish(model_states({"R%d" % i: circle(i, seconds) for i in range(args.robots)}))

    background(read_stdin, ticks)
    ticks.run(publish_once)
    ticks.said()


def tf_node(args):
    """One of the tf publishers: robots INDEX * N / K up to (INDEX + 1) * N / K."""
    from geometry_msgs.msg import Quaternion, Transform, TransformStamped, Vector3
    from std_msgs.msg import Header
    from tf2_msgs.msg import TFMessage
    rospy.init_node("bench_tf_%d" % args.index, anonymous=True)
    publisher = rospy.Publisher(args.topic, TFMessage, queue_size=10)
    mine = range(args.index * args.robots // args.publishers, (args.index + 1) * args.robots // args.publishers)
    ticks = Ticks(args.rate)

    def publish_once():
        seconds = time.monotonic() - ticks.start
        stamp = rospy.Time.now()
        transforms = []
        for i in mine:
            x, y = circle(i, seconds)
            transforms.append(TransformStamped(header=Header(stamp=stamp, frame_id=args.frame), child_frame_id="R%d/base_link" % i,
                                               transform=Transform(translation=Vector3(x, y, 0.0),
                                                                   rotation=Quaternion(0.0, 0.0, 0.0, 1.0))))
        publisher.publish(TFMessage(transforms=transforms))

    background(read_stdin, ticks)
    ticks.run(publish_once)
    ticks.said()


def tf_mode(args):
    """Starts a node per publisher (a process each: rospy has one node a process); ends them as stdin ends."""
    signal.signal(signal.SIGTERM, lambda *ignored: sys.exit(0))
    nodes = []
    try:
        for index in range(args.publishers):
            command = [sys.executable, os.path.abspath(__file__), "--mode", "tf", "--index", str(index), "--publishers",
                       str(args.publishers), "--robots", str(args.robots), "--rate", str(args.rate), "--topic", args.topic,
                       "--frame", args.frame]
            nodes.append(subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True))
        for _ in sys.stdin:
            pass
    finally:
        for node in nodes:
            node.stdin.close()  # its stdin ends: it stops and says what it sent
        sent = 0
        seconds = 0.0
        for node in nodes:
            try:
                node.wait(timeout=10)
            except subprocess.TimeoutExpired:
                node.kill()
                node.wait()
            for line in node.stdout.read().splitlines():
                words = line.split()
                if len(words) >= 5 and words[0] == "sent":
                    sent += int(words[1])
                    seconds = max(seconds, float(words[4]))
        print("sent %d messages in %.1f s (%.1f a second, %d publishers)" % (sent, seconds, sent / max(seconds, 1e-9), len(nodes)),
              flush=True)


def main():
    args = options(rospy.myargv(sys.argv)[1:])
    if args.mode == "place":
        place_mode(args)
    elif args.mode == "model_states":
        model_states_mode(args)
    elif args.index >= 0:
        tf_node(args)
    else:
        tf_mode(args)


if __name__ == "__main__":
    main()
