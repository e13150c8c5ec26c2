# proactive-robotics: the application's image, built from the sources by `docker compose build`
# (or `docker compose up --build`) on a machine with Docker alone. Every service of
# docker-compose.yml but MySQL runs it: java -jar /app/proactive.jar engine|robot|watch ...
#
#   docker build -t proactive-robotics .
#
# The base images are build arguments: any JDK 17 builds it, any Java 17 runtime runs it.
ARG BUILD_IMAGE=eclipse-temurin:17-jdk
ARG RUNTIME_IMAGE=eclipse-temurin:17-jre

FROM ${BUILD_IMAGE} AS build
WORKDIR /src
# First the build files alone, built over empty sources: Maven and the dependencies land in a
# layer of their own, which a change to the sources does not invalidate.
COPY mvnw pom.xml ./
COPY .mvn .mvn
COPY mcap/pom.xml mcap/
COPY db/pom.xml db/
COPY engine/pom.xml engine/
COPY scenario-testkit/pom.xml scenario-testkit/
COPY sim2d/pom.xml sim2d/
COPY robot-controller/pom.xml robot-controller/
COPY app/pom.xml app/
COPY e2e/pom.xml e2e/
COPY bench/pom.xml bench/
RUN ./mvnw -B -ntp -q package -DskipTests -pl app -am
# Then the sources: the jar app/target/proactive.jar, as `./mvnw package` makes it.
COPY . .
RUN ./mvnw -B -ntp -q package -DskipTests -pl app -am \
 && cp app/target/proactive.jar /proactive.jar

FROM ${RUNTIME_IMAGE}
# the messages' dashes and units print as themselves whatever the base image's locale
ENV LANG=C.UTF-8
COPY --from=build /proactive.jar /app/proactive.jar
# the bundled worlds as files too (docker-compose.yml mounts ./worlds over them, for your own)
COPY worlds /app/worlds
WORKDIR /work
CMD ["java", "-jar", "/app/proactive.jar", "--help"]
