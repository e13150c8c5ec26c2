package org.proactiverobotics.app.deploy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;

/**
 * The folder an embedded H2 database's files go in ({@code jdbc:h2:/data/mission},
 * {@code jdbc:h2:file:~/mission}), made ready before the first connection: H2 itself prints a
 * long stack trace on the console when it cannot write there, before it fails.
 */
final class H2Folder {

    private H2Folder() {
    }

    /**
     * Creates the database's folder when missing, as H2 would.
     *
     * @param url a JDBC URL
     * @return one line saying why the folder of a file-based H2 URL cannot be used and what to do,
     *         or null when it can (or the URL is not one: another database, H2 in memory or on a server)
     */
    static String problem(String url) {
        Path folder = folderOf(url);
        if (folder == null) {
            return null;
        }
        String fix = ": give --db a path in a folder you can write to";
        if (Files.exists(folder) && !Files.isDirectory(folder)) {
            return "the H2 database's folder " + folder + " is a file, not a folder" + fix;
        }
        try {
            Files.createDirectories(folder);
        } catch (IOException e) {
            return "cannot create the H2 database's folder " + folder + " (" + OutputDirectory.reason(e) + ")" + fix;
        }
        return Files.isWritable(folder) ? null : "the H2 database's folder " + folder + " is not writable" + fix;
    }

    /** @return the folder of a file-based H2 database's files, or null for any other URL */
    static Path folderOf(String url) {
        if (url == null || !url.startsWith("jdbc:h2:")) {
            return null;
        }
        String name = url.substring("jdbc:h2:".length());
        int semicolon = name.indexOf(';');
        name = semicolon < 0 ? name : name.substring(0, semicolon);
        name = name.startsWith("file:") ? name.substring("file:".length()) : name;
        if (name.startsWith("~")) {
            name = System.getProperty("user.home") + name.substring(1);
        } else if (!(name.startsWith("/") || name.startsWith("./") || name.startsWith("../"))) {
            return null; // mem:, tcp://, ssl://, another file system of H2's, or a name H2 refuses itself
        }
        try {
            return Path.of(name).toAbsolutePath().normalize().getParent();
        } catch (InvalidPathException e) {
            return null;
        }
    }
}
