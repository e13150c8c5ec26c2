package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.e2e.Deployment.Compose;

/**
 * docker-compose.yml (no Docker here): its services, pinned images, health checks, named
 * volume, credentials from .env, and init scripts that are the ones the two-process tests apply.
 */
class ComposeFileTest {

    private final Compose compose = Compose.load();

    ComposeFileTest() throws Exception {
    }

    @Test
    void mysqlEngineAndRobotServicesOnPinnedImages() {
        assertThat(compose.services()).containsOnlyKeys("mysql", "engine", "robot", "watch");
        assertThat(compose.service("mysql").image()).matches("mysql:8\\.4\\.\\d+");
        assertThat(compose.service("engine").image()).isEqualTo("eclipse-temurin:17-jre");
        assertThat(compose.service("robot").image()).isEqualTo("eclipse-temurin:17-jre");
    }

    @Test
    void everyServiceHasAHealthCheckAndTheProcessesWaitForAHealthyDatabase() {
        for (String name : List.of("mysql", "engine", "robot", "watch")) {
            assertThat(compose.service(name).healthcheck()).as(name).containsKeys("test", "interval", "retries");
        }
        assertThat(String.valueOf(compose.service("mysql").healthcheck().get("test")))
                .contains("mysqladmin").contains("ping").contains("127.0.0.1");
        for (String name : List.of("engine", "robot")) {
            assertThat(compose.service(name).dependsOn()).as(name)
                    .containsEntry("mysql", Map.of("condition", "service_healthy"));
            assertThat(String.valueOf(compose.service(name).healthcheck().get("test"))).contains("/tmp/proactive.heartbeat");
            assertThat(compose.service(name).command()).as(name).containsSequence("--heartbeat", "/tmp/proactive.heartbeat");
        }
    }

    @Test
    void theDataLivesInANamedVolume() {
        assertThat(compose.volumes()).containsKey("mysql-data");
        assertThat(compose.service("mysql").volumes()).contains("mysql-data:/var/lib/mysql");
    }

    @Test
    void theInitScriptsAreTheRootSchemaThenTheUsersScript() throws Exception {
        assertThat(compose.mysqlInitVolumes()).containsExactly(
                "./schema.sql:/docker-entrypoint-initdb.d/01-schema.sql:ro",
                "./deploy/mysql-init/02-users.sh:/docker-entrypoint-initdb.d/02-users.sh:ro");
        assertThat(compose.service("mysql").volumes()).contains("./deploy/users.sql:/proactive/users.sql:ro");
        assertThat(compose.service("mysql").environment()).containsEntry("PROACTIVE_USERS_SQL", "/proactive/users.sql")
                .containsEntry("MYSQL_DATABASE", "proactive");
        for (String volume : compose.service("mysql").volumes()) {
            if (volume.startsWith("./")) {
                assertThat(Deployment.root().resolve(volume.split(":")[0])).as(volume).isRegularFile();
            }
        }
        // sourced, not executed, by the image's entrypoint: it then has docker_process_sql
        assertThat(Files.isExecutable(Deployment.root().resolve("deploy/mysql-init/02-users.sh"))).isFalse();
    }

    @Test
    void theProcessesRunTheMountedJarAsTheirLeastPrivilegeUsers() {
        Compose.Service engine = compose.service("engine");
        Compose.Service robot = compose.service("robot");
        assertThat(engine.volumes()).contains("./app/target/proactive.jar:/app/proactive.jar:ro");
        assertThat(robot.volumes()).contains("./app/target/proactive.jar:/app/proactive.jar:ro", "./worlds:/app/worlds:ro");
        assertThat(engine.command()).startsWith("java", "-jar", "/app/proactive.jar", "engine")
                .containsSequence("--db", "jdbc:mysql://mysql:3306/proactive").containsSequence("--db-user", "proactive_engine");
        assertThat(robot.command()).startsWith("java", "-jar", "/app/proactive.jar", "robot")
                .containsSequence("--world", "/app/worlds/reference-arena.json")
                .containsSequence("--db", "jdbc:mysql://mysql:3306/proactive").containsSequence("--db-user", "proactive_robot");
    }

    @Test
    void credentialsComeFromDotEnvWhoseExampleIsCommittedAndWhoseRealOneIsIgnored() throws Exception {
        assertThat(String.valueOf(compose.service("mysql").environment().get("MYSQL_ROOT_PASSWORD"))).startsWith("${MYSQL_ROOT_PASSWORD");
        assertThat(String.valueOf(compose.service("engine").environment().get("PROACTIVE_DB_PASSWORD"))).startsWith("${ENGINE_DB_PASSWORD");
        assertThat(String.valueOf(compose.service("robot").environment().get("PROACTIVE_DB_PASSWORD"))).startsWith("${ROBOT_DB_PASSWORD");
        Path root = Deployment.root();
        assertThat(Files.readString(root.resolve(".env.example")))
                .contains("MYSQL_ROOT_PASSWORD=", "ENGINE_DB_PASSWORD=", "ROBOT_DB_PASSWORD=");
        assertThat(Files.readAllLines(root.resolve(".gitignore"))).contains(".env");
        assertThat(Files.readString(root.resolve("docker-compose.yml"))).doesNotContain("change-me");
    }
}
