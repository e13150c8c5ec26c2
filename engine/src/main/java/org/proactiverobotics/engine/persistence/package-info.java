/**
 * The engine's persistence over JDBC: {@link org.proactiverobotics.engine.persistence.JdbcStateStore}
 * saves what an iteration ends with (iteration number, nextQueue, shared memory, failures) in the
 * tables of schema.sql, {@link org.proactiverobotics.engine.persistence.StateCodec} turns rules and
 * memory into JSON, {@link org.proactiverobotics.engine.persistence.IterationTransaction} makes an
 * iteration's writes and its saved state one transaction, and
 * {@link org.proactiverobotics.engine.persistence.CommitGroup} commits several robots' iterations as
 * one.
 *
 * <p>It implements the core's {@link org.proactiverobotics.engine.StateStore}; the core
 * ({@code org.proactiverobotics.engine}) never imports this package, so the engine runs without
 * a database ({@link org.proactiverobotics.engine.StateStore#none()}).
 */
package org.proactiverobotics.engine.persistence;
