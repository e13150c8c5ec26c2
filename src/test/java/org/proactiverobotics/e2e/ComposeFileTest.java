package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.e2e.Deployment.Compose;
import org.yaml.snakeyaml.Yaml;

/**
 * docker-compose.yml as data: its services, pinned images, the application's image built from
 * the Dockerfile, health checks, named volume, credentials and project name from .env, and init
 * scripts that are the ones the two-process tests apply. (.ci/compose runs it for real, with the
 * override checked here, which swaps image names only.)
 */
class ComposeFileTest {

    private final Compose compose = Compose.load();

    ComposeFileTest() throws Exception {
    }

    @Test
    void mysqlOnAPinnedImageAndTheProcessesOnTheApplicationsImageBuiltFromTheDockerfile() throws Exception {
        assertThat(compose.services()).containsOnlyKeys("mysql", "engine", "robot", "watch", "fleet-engine");
        assertThat(compose.service("mysql").image()).matches("mysql:8\\.4\\.\\d+");
        for (String name : List.of("engine", "robot", "watch", "fleet-engine")) {
            assertThat(compose.service(name).image()).as(name).isEqualTo("proactive-robotics:local");
            assertThat(compose.service(name).get("build")).as(name).isEqualTo(Map.of("context", "."));
        }
        String dockerfile = Files.readString(Deployment.root().resolve("Dockerfile"));
        // two stages, the public base images as defaults of build arguments
        assertThat(dockerfile).contains("ARG BUILD_IMAGE=eclipse-temurin:17-jdk", "ARG RUNTIME_IMAGE=eclipse-temurin:17-jre",
                "FROM ${BUILD_IMAGE} AS build", "FROM ${RUNTIME_IMAGE}", "COPY --from=build /proactive.jar /app/proactive.jar");
        assertThat(Files.readAllLines(Deployment.root().resolve(".dockerignore"))).contains(".env", "**/target");
    }

    @Test
    void theProjectNameComesFromDotEnvNotFromATopLevelNameWhichComposeV1Refuses() throws Exception {
        assertThat(compose.topLevel()).doesNotContainKey("name");
        assertThat(Files.readAllLines(Deployment.root().resolve(".env.example"))).contains("COMPOSE_PROJECT_NAME=proactive-robotics");
    }

    @Test
    @SuppressWarnings("unchecked")
    void theCiOverrideSwapsImageNamesOnly() throws Exception {
        Map<String, Object> services;
        try (InputStream in = Files.newInputStream(Deployment.root().resolve(".ci/compose-images/docker-compose.ci.yml"))) {
            Map<String, Object> override = new Yaml().load(in);
            assertThat(override).containsOnlyKeys("services");
            services = (Map<String, Object>) override.get("services");
        }
        assertThat(services.get("mysql")).isEqualTo(Map.of("image", "proactive-ci/mariadb:10.11"));
        for (String name : List.of("engine", "robot", "watch", "fleet-engine")) {
            // the base images of the application's build, and the network that build needs on the CI's dockerd
            assertThat(services.get(name)).as(name).isEqualTo(Map.of("build", Map.of("network", "host",
                    "args", Map.of("BUILD_IMAGE", "proactive-ci/jdk:17", "RUNTIME_IMAGE", "proactive-ci/jre:17"))));
        }
    }

    @Test
    void everyServiceHasAHealthCheckAndTheProcessesWaitForAHealthyDatabase() {
        for (String name : List.of("mysql", "engine", "robot", "watch", "fleet-engine")) {
            assertThat(compose.service(name).healthcheck()).as(name).containsKeys("test", "interval", "retries");
        }
        assertThat(String.valueOf(compose.service("mysql").healthcheck().get("test")))
                .contains("mysqladmin").contains("ping").contains("127.0.0.1");
        for (String name : List.of("engine", "robot", "fleet-engine")) {
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
    void theProcessesRunTheImagesJarAsTheirLeastPrivilegeUsers() {
        Compose.Service engine = compose.service("engine");
        Compose.Service robot = compose.service("robot");
        for (String name : List.of("engine", "robot", "watch")) {
            assertThat(compose.service(name).volumes()).as(name + ": the jar is the image's").noneMatch(v -> v.contains("target"));
        }
        assertThat(robot.volumes()).contains("./worlds:/app/worlds:ro", "./runs:/work/runs");
        assertThat(engine.command()).startsWith("java", "-jar", "/app/proactive.jar", "engine")
                .containsSequence("--db", "jdbc:mysql://mysql:3306/proactive").containsSequence("--db-user", "proactive_engine");
        assertThat(robot.command()).startsWith("java", "-jar", "/app/proactive.jar", "robot")
                .containsSequence("--world", "/app/worlds/reference-arena.json")
                .containsSequence("--db", "jdbc:mysql://mysql:3306/proactive").containsSequence("--db-user", "proactive_robot");
        // one engine per robot: ROBOT_ID (default 1) picks the pair, e.g. ROBOT_ID=2 docker compose run robot
        for (String name : List.of("engine", "robot", "watch")) {
            assertThat(compose.service(name).rawCommand()).as(name).containsSequence("--robot-id", "${ROBOT_ID:-1}");
        }
        // a fleet: one engine process for the robots of ROBOT_IDS, scaled to K engines that share them (profile fleet)
        Compose.Service fleet = compose.service("fleet-engine");
        assertThat(fleet.rawCommand()).containsSequence("--robot-ids", "${ROBOT_IDS:-1-4}")
                .containsSequence("--db-user", "proactive_engine");
        assertThat(String.valueOf(fleet.environment().get("PROACTIVE_DB_PASSWORD"))).startsWith("${ENGINE_DB_PASSWORD");
        assertThat(fleet.get("profiles")).isEqualTo(List.of("fleet"));
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
