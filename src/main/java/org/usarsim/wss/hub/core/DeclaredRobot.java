package org.usarsim.wss.hub.core;

import java.net.InetAddress;

/**
 * A robot declared in the configuration ({@code wss.robot.NAME = ADDRESS}) instead of registering
 * by INIT: present from Start to Stop, its programs connecting from and listening on {@code address}.
 */
public record DeclaredRobot(String name, InetAddress address) {
}
