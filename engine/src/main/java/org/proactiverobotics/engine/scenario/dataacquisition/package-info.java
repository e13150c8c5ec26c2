/**
 * Scenario 1, Data acquisition: GetGPS, GetDS, GetIU (and GetBattery, GetOdometry) each make sure
 * a recent reading of their sensor exists and otherwise ask the robot for one. No CommandArray slot.
 */
package org.proactiverobotics.engine.scenario.dataacquisition;
