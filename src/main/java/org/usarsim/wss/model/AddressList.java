package org.usarsim.wss.model;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/** The rule of a {@link Setting.Type#ADDRESSES} value: a list of client addresses written as numbers ({@link Setting#addressList}). */
final class AddressList {

    private static final String V4 = "(25[0-5]|2[0-4][0-9]|1[0-9][0-9]|[1-9]?[0-9])(\\.(25[0-5]|2[0-4][0-9]|1[0-9][0-9]|[1-9]?[0-9])){3}";

    private AddressList() {
    }

    /** The addresses of the list, or null when the text is not such a list (as {@link Setting#addressList} says). */
    static List<InetAddress> parse(String text) {
        Set<InetAddress> addresses = new LinkedHashSet<>();
        for (String item : text.split(",", -1)) {
            InetAddress address = numericAddress(item.strip());
            if (address == null || address.isAnyLocalAddress()) {
                return null; // the wildcard address is a server's to listen on: no client comes from it
            }
            addresses.add(address);
        }
        return List.copyOf(addresses);
    }

    private static InetAddress numericAddress(String text) {
        boolean v4 = text.matches(V4);
        boolean v6 = text.contains(":") && text.matches("[0-9A-Fa-f:.]+");
        if (!v4 && !v6) {
            return null;
        }
        try {
            return InetAddress.getByName(text); // a literal: parsed, not looked up
        } catch (UnknownHostException e) {
            return null;
        }
    }
}
