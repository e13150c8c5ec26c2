package org.proactiverobotics.bench.mission;

import java.io.PrintWriter;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.SQLFeatureNotSupportedException;
import java.sql.Statement;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.LongAdder;
import java.util.logging.Logger;
import javax.sql.DataSource;

/**
 * A DataSource that counts the statements run through it: reads (queries: executeQuery, or
 * execute of a SELECT) and writes (executeUpdate, executeBatch, execute of anything else), in
 * total and per SQL text. A benchmark harness tool: dynamic proxies around the connection and
 * its statements, everything else passed through.
 */
public final class CountingDataSource implements DataSource {

    private final DataSource target;
    private final LongAdder reads = new LongAdder();
    private final LongAdder writes = new LongAdder();
    private final Map<String, LongAdder> bySql = new java.util.concurrent.ConcurrentHashMap<>();

    /** @param target the data source to count */
    public CountingDataSource(DataSource target) {
        this.target = target;
    }

    /** @return queries run so far */
    public long reads() {
        return reads.sum();
    }

    /** @return updates, inserts, deletes (and batches, one each) run so far */
    public long writes() {
        return writes.sum();
    }

    /** Forgets every count. */
    public void reset() {
        reads.reset();
        writes.reset();
        bySql.clear();
    }

    /** @return per SQL statement text (whitespace squeezed), how many times it ran, most frequent first */
    public Map<String, Long> bySql() {
        TreeMap<String, Long> sorted = new TreeMap<>();
        bySql.forEach((sql, n) -> sorted.put(sql, n.sum()));
        Map<String, Long> out = new LinkedHashMap<>();
        sorted.entrySet().stream().sorted((a, b) -> Long.compare(b.getValue(), a.getValue()))
                .forEach(e -> out.put(e.getKey(), e.getValue()));
        return out;
    }

    private void count(String sql, boolean read) {
        (read ? reads : writes).increment();
        bySql.computeIfAbsent(sql == null ? "?" : sql.replaceAll("\\s+", " ").trim(), k -> new LongAdder()).increment();
    }

    private static boolean isSelect(String sql) {
        return sql != null && sql.stripLeading().regionMatches(true, 0, "SELECT", 0, 6);
    }

    @Override
    public Connection getConnection() throws SQLException {
        return wrap(target.getConnection());
    }

    @Override
    public Connection getConnection(String username, String password) throws SQLException {
        return wrap(target.getConnection(username, password));
    }

    private Connection wrap(Connection c) {
        return (Connection) Proxy.newProxyInstance(Connection.class.getClassLoader(), new Class<?>[] {Connection.class},
                (proxy, method, args) -> {
                    Object result = invoke(c, method, args);
                    if (result instanceof PreparedStatement ps && method.getName().startsWith("prepare")) {
                        return statement(ps, PreparedStatement.class, (String) args[0]);
                    }
                    if (result instanceof Statement s && method.getName().equals("createStatement")) {
                        return statement(s, Statement.class, null);
                    }
                    return result;
                });
    }

    private <T extends Statement> T statement(T target, Class<T> type, String preparedSql) {
        InvocationHandler handler = (proxy, method, args) -> {
            String sql = args != null && args.length > 0 && args[0] instanceof String s ? s : preparedSql;
            switch (method.getName()) {
                case "executeQuery" -> count(sql, true);
                case "executeUpdate", "executeLargeUpdate", "executeBatch", "executeLargeBatch" -> count(sql, false);
                case "execute" -> count(sql, isSelect(sql));
                default -> { }
            }
            return invoke(target, method, args);
        };
        return type.cast(Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] {type}, handler));
    }

    private static Object invoke(Object target, Method method, Object[] args) throws Throwable {
        try {
            return method.invoke(target, args);
        } catch (InvocationTargetException e) {
            throw e.getCause();
        }
    }

    @Override
    public PrintWriter getLogWriter() throws SQLException {
        return target.getLogWriter();
    }

    @Override
    public void setLogWriter(PrintWriter out) throws SQLException {
        target.setLogWriter(out);
    }

    @Override
    public void setLoginTimeout(int seconds) throws SQLException {
        target.setLoginTimeout(seconds);
    }

    @Override
    public int getLoginTimeout() throws SQLException {
        return target.getLoginTimeout();
    }

    @Override
    public Logger getParentLogger() throws SQLFeatureNotSupportedException {
        return target.getParentLogger();
    }

    @Override
    public <T> T unwrap(Class<T> iface) throws SQLException {
        return target.unwrap(iface);
    }

    @Override
    public boolean isWrapperFor(Class<?> iface) throws SQLException {
        return target.isWrapperFor(iface);
    }
}
