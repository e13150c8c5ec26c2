/**
 * Communication layers between the engine and the robot beside the database (the paper's
 * "different communication layer"): {@link org.proactiverobotics.app.link.DirectLink}, an
 * in-process link over plain memory that implements the robot side's {@code RobotLink} and the
 * engine side's table interfaces with the semantics of the JDBC tables, and
 * {@link org.proactiverobotics.app.link.EngineTables}, what the engine side is wired with
 * whichever layer is used.
 */
package org.proactiverobotics.app.link;
