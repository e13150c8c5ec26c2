package org.proactiverobotics.e2e;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.time.Duration;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A database outage for the tests, since the shared MariaDB cannot be stopped: a TCP proxy on a
 * loopback ephemeral port forwarding to the database (loopback only). {@link #cut(Duration)}
 * resets every open connection and refuses new ones (accepted, then reset at once) for a while,
 * as a stopped server would; then it forwards again. {@link #slowToAnswer(Duration)} makes it a
 * server that is up but busy: every new connection waits that long before the database sees it.
 */
final class TcpProxy implements AutoCloseable {

    private final ServerSocket server;
    private final InetSocketAddress target;
    private final Set<Socket> open = ConcurrentHashMap.newKeySet();
    private final AtomicLong accepted = new AtomicLong();
    private final AtomicLong refused = new AtomicLong();
    private final Thread acceptor;
    private volatile long refuseUntilNanos;
    private volatile boolean cutting;
    private volatile boolean closed;
    private volatile long answerDelayNanos;

    /**
     * @param targetHost the database host: a loopback address
     * @param targetPort its port
     */
    TcpProxy(String targetHost, int targetPort) throws IOException {
        InetAddress address = InetAddress.getByName(targetHost);
        if (!address.isLoopbackAddress()) {
            throw new IllegalArgumentException("the test proxy forwards to loopback addresses only: " + targetHost);
        }
        this.target = new InetSocketAddress(address, targetPort);
        this.server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        this.acceptor = new Thread(this::acceptLoop, "tcp-proxy-" + server.getLocalPort());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    /** @return the port to connect to instead of the database's */
    int port() {
        return server.getLocalPort();
    }

    /** @return connections forwarded so far */
    long accepted() {
        return accepted.get();
    }

    /** @return connections refused during cuts so far */
    long refused() {
        return refused.get();
    }

    /** Resets every open connection and refuses new ones for this long (returns at once). */
    void cut(Duration outage) {
        cutting = true;
        refuseUntilNanos = System.nanoTime() + outage.toNanos();
        for (Socket s : open) {
            reset(s);
        }
        open.clear();
    }

    /**
     * From now on, every new connection is accepted at once but reaches the database only after
     * this delay, as on a server starved of processor time (returns at once).
     */
    void slowToAnswer(Duration delay) {
        answerDelayNanos = delay.toNanos();
    }

    /** @return whether new connections are refused now */
    boolean down() {
        return cutting && System.nanoTime() - refuseUntilNanos < 0;
    }

    private void acceptLoop() {
        while (!closed) {
            Socket client;
            try {
                client = server.accept();
            } catch (IOException e) {
                return; // closed
            }
            if (down()) {
                refused.incrementAndGet();
                reset(client);
                continue;
            }
            long delay = answerDelayNanos;
            if (delay > 0) {
                Thread slow = new Thread(() -> {
                    java.util.concurrent.locks.LockSupport.parkNanos(delay);
                    forward(client);
                }, "tcp-proxy-slow");
                slow.setDaemon(true);
                slow.start();
            } else {
                forward(client);
            }
        }
    }

    private void forward(Socket client) {
        Socket upstream = new Socket();
        try {
            upstream.connect(target, 2_000);
            client.setTcpNoDelay(true);
            upstream.setTcpNoDelay(true);
        } catch (IOException e) {
            reset(client);
            reset(upstream);
            return;
        }
        accepted.incrementAndGet();
        open.add(client);
        open.add(upstream);
        pump(client, upstream);
        pump(upstream, client);
    }

    private void pump(Socket from, Socket to) {
        Thread t = new Thread(() -> {
            byte[] buffer = new byte[16 * 1024];
            try (InputStream in = from.getInputStream(); OutputStream out = to.getOutputStream()) {
                int n;
                while ((n = in.read(buffer)) >= 0) {
                    out.write(buffer, 0, n);
                    out.flush();
                }
            } catch (IOException e) {
                // reset or closed: end both directions below
            } finally {
                reset(from);
                reset(to);
                open.remove(from);
                open.remove(to);
            }
        }, "tcp-proxy-pump");
        t.setDaemon(true);
        t.start();
    }

    /** Closes with an RST (linger 0), as a server that went away. */
    private static void reset(Socket s) {
        try {
            if (!s.isClosed()) {
                s.setSoLinger(true, 0);
            }
        } catch (SocketException e) {
            // closing anyway
        }
        try {
            s.close();
        } catch (IOException e) {
            // nothing to do
        }
    }

    @Override
    public void close() throws IOException {
        closed = true;
        server.close();
        for (Socket s : open) {
            reset(s);
        }
        open.clear();
    }
}
