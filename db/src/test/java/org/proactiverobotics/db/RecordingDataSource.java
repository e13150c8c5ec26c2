package org.proactiverobotics.db;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.Statement;
import java.util.List;
import javax.sql.DataSource;

/**
 * A test's view of what goes to the server through a data source: each statement's SQL as it is
 * run (a prepared statement's text, or a plain statement's), and {@code commit}, {@code rollback}
 * and {@code setAutoCommit} by name. Everything is passed through to the real data source.
 */
public final class RecordingDataSource {

    private RecordingDataSource() {
    }

    /**
     * @param target the data source
     * @param sent   where to record, in order (a thread-safe list when several threads use it)
     * @return the data source, recording
     */
    public static DataSource of(DataSource target, List<String> sent) {
        return proxy(DataSource.class, target, (method, args, result) -> {
            if (!method.getName().equals("getConnection")) {
                return result;
            }
            Connection c = (Connection) result;
            return proxy(Connection.class, c, (cm, cargs, r) -> {
                if (List.of("commit", "rollback", "setAutoCommit").contains(cm.getName())) {
                    sent.add(cm.getName());
                }
                if (!(r instanceof Statement s)) {
                    return r;
                }
                String prepared = cm.getName().equals("prepareStatement") ? (String) cargs[0] : null;
                Class<? extends Statement> type = r instanceof PreparedStatement ? PreparedStatement.class : Statement.class;
                return proxy(type, s, (sm, sargs, sr) -> sr, (sm, sargs) -> {
                    if (sm.getName().startsWith("execute")) {
                        sent.add(prepared != null ? prepared : sargs != null && sargs.length > 0 ? String.valueOf(sargs[0]) : sm.getName());
                    }
                });
            });
        });
    }

    /** What to return for a call, given the real result. */
    private interface After {
        Object apply(Method method, Object[] args, Object result) throws Throwable;
    }

    /** What to note before a call. */
    private interface Before {
        void accept(Method method, Object[] args);
    }

    private static <T> T proxy(Class<T> type, Object target, After after) {
        return proxy(type, target, after, (m, a) -> {
        });
    }

    private static <T> T proxy(Class<T> type, Object target, After after, Before before) {
        return type.cast(Proxy.newProxyInstance(RecordingDataSource.class.getClassLoader(), new Class<?>[] {type},
                (p, method, args) -> {
                    before.accept(method, args);
                    Object result;
                    try {
                        result = method.invoke(target, args);
                    } catch (InvocationTargetException e) {
                        throw e.getCause();
                    }
                    return after.apply(method, args, result);
                }));
    }
}
