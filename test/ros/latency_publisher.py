#!/usr/bin/env python3
"""Publishes robots' poses on a real ROS 1 graph for RosbridgeBenchmark (docs/performance.md,
"Positions over rosbridge") and RealRosbridgeCheck (docs/ros.md, "Checked against a real
rosbridge"). rospy only; run it with a ROS environment sourced. It stops when its standard input
ends (the benchmark closes it), or on SIGINT / SIGTERM.

--mode place (the latency run): gazebo_msgs/ModelStates on --topic at --rate, with the models
    the benchmark places by writing `place NAME X Y` lines to standard input (and --extra models
    that stand still, as Gazebo's ground_plane does). A place is published at once, out of the
    tick (the tick then starts again from it), and said on standard output as
    `published NAME <time.time_ns() just before the publish>`.
--mode model_states (the CPU run): --robots robots R0 .. R{N-1}, each moving on a circle of
    30 m around its own centre, the same paths as the benchmark's USARSim peer, at --rate.
--mode tf (the CPU run): --publishers nodes of their own, each publishing one
    tf2_msgs/TFMessage with its share of the --robots robots (--frame -> Ri/base_link, stamped
    with the wall clock) at --rate on --topic; with --per-robot one TFMessage for each robot.
--mode odom: nav_msgs/Odometry of each robot on its own topic (--topic with {robot} in it), in
    --frame, at --rate, from one node; with --delay-each S robot i's publisher is advertised only
    (i + 1) * S seconds after the start (a robot whose odometry starts late), so that they start
    one after another.
--mode bad: as odom, but after --good seconds of good poses every pose's x is NaN (rosbridge 0.11
    writes it as null): messages a reader cannot use. Says `bad from now` when it turns.
--mode tf_static: one transform --frame -> --child (translation --x, --y, rotation --yaw degrees
    about z), published once on a latched --topic; the node then stays until its stdin ends (a
    latched message goes with its publisher).

The robots are R0 .. R{N-1} (--robots N), or --names A,B,C. With --spacing M above 0 robot i
stands still at (--x + i * M, --y); otherwise it moves on its circle.

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
    parser.add_argument("--mode", choices=["place", "model_states", "tf", "odom", "bad", "tf_static"], default="place")
    parser.add_argument("--rate", type=float, default=5.0, help="messages a second (of each publisher)")
    parser.add_argument("--topic", help="default: /bench/model_states, /bench/tf, /bench/{robot}/odom or /bench/tf_static")
    parser.add_argument("--robots", type=int, default=100, help="model_states and tf: how many robots")
    parser.add_argument("--publishers", type=int, default=10, help="tf: how many nodes publish on the topic")
    parser.add_argument("--names", help="the robots' names, comma-separated (instead of R0 .. R{N-1})")
    parser.add_argument("--frame", help="tf, odom: the frame of every robot (world); tf_static: the parent frame (map)")
    parser.add_argument("--child", default="world", help="tf_static: the child frame")
    parser.add_argument("--spacing", type=float, default=0.0, help="above 0: robot i stands at (X + i * SPACING, Y)")
    parser.add_argument("--x", type=float, default=0.0, help="X: where standing robots start; tf_static: its translation")
    parser.add_argument("--y", type=float, default=0.0, help="Y: where standing robots stand; tf_static: its translation")
    parser.add_argument("--yaw", type=float, default=0.0, help="tf_static: its rotation about z, in degrees")
    parser.add_argument("--per-robot", action="store_true", help="tf: one TFMessage for each robot, not one for all")
    parser.add_argument("--delay-each", type=float, default=0.0, help="odom, bad: robot i advertised (i + 1) * S s late")
    parser.add_argument("--good", type=float, default=0.0, help="bad: seconds of good poses before the NaNs")
    parser.add_argument("--extra", type=int, default=1, help="place: models besides the robots placed (ground_plane, ...)")
    parser.add_argument("--index", type=int, default=-1, help=argparse.SUPPRESS)  # tf: this node is publisher INDEX
    result = parser.parse_args(argv)
    if result.topic is None:
        result.topic = {"tf": "/bench/tf", "odom": "/bench/{robot}/odom", "bad": "/bench/{robot}/odom",
                        "tf_static": "/bench/tf_static"}.get(result.mode, "/bench/model_states")
    if result.frame is None:
        result.frame = "map" if result.mode == "tf_static" else "world"
    if result.rate <= 0 or result.robots < 1 or result.publishers < 1:
        parser.error("--rate, --robots and --publishers must be above 0")
    if result.mode in ("odom", "bad") and "{robot}" not in result.topic:
        parser.error("--topic needs {robot} in mode " + result.mode)
    return result


def robot_names(args):
    """--names, or R0 .. R{N-1}."""
    if args.names:
        return [name for name in args.names.split(",") if name]
    return ["R%d" % i for i in range(args.robots)]


def place(args, i, seconds):
    """Where robot i is: standing in its row with --spacing, else on its circle."""
    if args.spacing > 0:
        return args.x + i * args.spacing, args.y
    return circle(i, seconds)


def circle(i, seconds):
    """Robot i at a time: on a circle of 30 m around its own centre (RosbridgeBenchmark's peer has the same)."""
    angle = seconds * 0.5 + i
    return (i % 10) * 20 + 30 * math.cos(angle), (i // 10) * 20 + 30 * math.sin(angle)


class Ticks:
    """The publishing loop's clock: a tick every 1 / rate, woken early by wake(); done when stdin ends. A tick's
    publish_once gives how many messages it sent (None: one)."""

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
            published = publish_once()
            self.sent += 1 if published is None else published
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
    names = robot_names(args)
    mine = range(args.index * len(names) // args.publishers, (args.index + 1) * len(names) // args.publishers)
    ticks = Ticks(args.rate)

    def publish_once():
        seconds = time.monotonic() - ticks.start
        stamp = rospy.Time.now()
        transforms = []
        for i in mine:
            x, y = place(args, i, seconds)
            transforms.append(TransformStamped(header=Header(stamp=stamp, frame_id=args.frame), child_frame_id="%s/base_link" % names[i],
                                               transform=Transform(translation=Vector3(x, y, 0.0),
                                                                   rotation=Quaternion(0.0, 0.0, 0.0, 1.0))))
        messages = [TFMessage(transforms=[one]) for one in transforms] if args.per_robot else [TFMessage(transforms=transforms)]
        for message in messages:
            publisher.publish(message)
        return len(messages)

    background(read_stdin, ticks)
    ticks.run(publish_once)
    ticks.said()


def tf_mode(args, argv):
    """Starts a node per publisher (a process each: rospy has one node a process, each given this one's
    arguments and its index); ends them as stdin ends."""
    signal.signal(signal.SIGTERM, lambda *ignored: sys.exit(0))
    nodes = []
    try:
        for index in range(args.publishers):
            command = [sys.executable, os.path.abspath(__file__)] + list(argv) + ["--index", str(index)]
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


def odom_mode(args):
    """Each robot's Odometry on its own topic from one node; robot i advertised (i + 1) * --delay-each s late.
    Mode bad: x is NaN once --good seconds have passed."""
    from geometry_msgs.msg import PoseWithCovariance
    from nav_msgs.msg import Odometry
    from std_msgs.msg import Header
    rospy.init_node("bench_odom", anonymous=True)
    names = robot_names(args)
    publishers = [None] * len(names)
    ticks = Ticks(args.rate)
    turned = [False]

    def publish_once():
        seconds = time.monotonic() - ticks.start
        bad = args.mode == "bad" and seconds >= args.good
        if bad and not turned[0]:
            turned[0] = True
            print("bad from now", flush=True)
        stamp = rospy.Time.now()
        sent = 0
        for i, name in enumerate(names):
            if publishers[i] is None:
                if seconds < (i + 1) * args.delay_each:
                    continue
                publishers[i] = rospy.Publisher(args.topic.replace("{robot}", name), Odometry, queue_size=10)
            x, y = place(args, i, seconds)
            message = Odometry(header=Header(stamp=stamp, frame_id=args.frame), child_frame_id="%s/base_link" % name,
                               pose=PoseWithCovariance(pose=pose(float("nan") if bad else x, y)))
            publishers[i].publish(message)
            sent += 1
        return sent

    background(read_stdin, ticks)
    ticks.run(publish_once)
    ticks.said()


def tf_static_mode(args):
    """--frame -> --child once, latched; then waits for its stdin to end."""
    from geometry_msgs.msg import Quaternion, Transform, TransformStamped, Vector3
    from std_msgs.msg import Header
    from tf2_msgs.msg import TFMessage
    rospy.init_node("bench_tf_static", anonymous=True)
    publisher = rospy.Publisher(args.topic, TFMessage, queue_size=1, latch=True)
    half = math.radians(args.yaw) / 2
    transform = TransformStamped(header=Header(stamp=rospy.Time.now(), frame_id=args.frame), child_frame_id=args.child,
                                 transform=Transform(translation=Vector3(args.x, args.y, 0.0),
                                                     rotation=Quaternion(0.0, 0.0, math.sin(half), math.cos(half))))
    ticks = Ticks(args.rate)
    publisher.publish(TFMessage(transforms=[transform]))
    ticks.sent = 1
    for _ in sys.stdin:
        pass
    ticks.said()


def main():
    argv = rospy.myargv(sys.argv)[1:]
    args = options(argv)
    if args.mode == "place":
        place_mode(args)
    elif args.mode == "model_states":
        model_states_mode(args)
    elif args.mode in ("odom", "bad"):
        odom_mode(args)
    elif args.mode == "tf_static":
        tf_static_mode(args)
    elif args.index >= 0:
        tf_node(args)
    else:
        tf_mode(args, argv)


if __name__ == "__main__":
    main()
