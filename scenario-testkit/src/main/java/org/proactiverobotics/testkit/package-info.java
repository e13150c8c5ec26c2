/**
 * The scenario test kit: test a proactive scenario of your own alone, on the real engine over an
 * embedded H2 database with the real schema, with the robot's readings scripted step by step.
 * Start with {@link org.proactiverobotics.testkit.ScenarioKit#builder()}.
 */
package org.proactiverobotics.testkit;
