/* test_file.c - output targets and the atomic writer (platform/file):
 * what hol_file_check_out accepts and refuses (special files made in a
 * temporary folder only), and a commit that finds its target turned into a
 * FIFO or a socket meanwhile refuses to rename over it.
 */
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cmocka.h>

#include "../platform/file/hol_file.h"

static char dir[64];

static const char *at(const char *name)
{
    static char p[2][256];
    static int k;
    k ^= 1;
    snprintf(p[k], sizeof p[k], "%s/%s", dir, name);
    return p[k];
}

static int setup(void **state)
{
    (void)state;
    strcpy(dir, "/tmp/holonomy-test-file.XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

/* A UNIX socket bound at path (left bound: the name stays). */
static void make_socket(const char *path)
{
    int fd = socket(AF_UNIX, SOCK_STREAM, 0);
    assert_true(fd >= 0);
    struct sockaddr_un a;
    memset(&a, 0, sizeof a);
    a.sun_family = AF_UNIX;
    assert_true(strlen(path) < sizeof a.sun_path);
    strcpy(a.sun_path, path);
    assert_int_equal(bind(fd, (struct sockaddr *)&a, sizeof a), 0);
    close(fd);
}

static void expect_refused(const char *path, const char *why)
{
    char msg[160] = "";
    assert_int_equal(hol_file_check_out(path, msg, sizeof msg), HOL_EARG);
    if (!strstr(msg, why))
        fail_msg("'%s': '%s', want '%s'", path, msg, why);
}

static void test_check_out(void **state)
{
    (void)state;
    char msg[160];
    /* accepted: a new name, a regular file, a link to a regular file */
    assert_int_equal(hol_file_check_out(at("new"), msg, sizeof msg), HOL_OK);
    FILE *f = fopen(at("reg"), "w");
    assert_non_null(f);
    fclose(f);
    assert_int_equal(hol_file_check_out(at("reg"), msg, sizeof msg), HOL_OK);
    assert_int_equal(symlink("reg", at("lreg")), 0);
    assert_int_equal(hol_file_check_out(at("lreg"), NULL, 0), HOL_OK);
    /* refused: everything else */
    assert_int_equal(mkfifo(at("fifo"), 0600), 0);
    expect_refused(at("fifo"), "is a FIFO");
    make_socket(at("sock"));
    expect_refused(at("sock"), "is a socket");
    assert_int_equal(mkdir(at("sub"), 0700), 0);
    expect_refused(at("sub"), "is a directory");
    expect_refused(at("sub/"), "ends in '/'");
    expect_refused(at("missing/x"), "folder that does not exist");
    expect_refused(at("reg/x"), "under a file");
    expect_refused("", "empty");
    assert_int_equal(symlink("fifo", at("lfifo")), 0);
    expect_refused(at("lfifo"), "symbolic link to a FIFO");
    assert_int_equal(symlink("nothing", at("dangling")), 0);
    expect_refused(at("dangling"), "symbolic link to nothing");
    assert_int_equal(symlink("loop", at("loop")), 0);
    expect_refused(at("loop"), "loop");
    if (mknod(at("null"), S_IFCHR | 0600, makedev(1, 3)) == 0)
        expect_refused(at("null"), "is a character device");
    else
        assert_int_equal(errno, EPERM); /* not root: no device nodes */
    /* the writer checks too, before making its temporary file */
    hol_file_atomic a;
    assert_int_equal(hol_file_atomic_open(&a, at("fifo")), HOL_EARG);
    assert_null(a.tmp);
    assert_int_equal(hol_file_write_atomic(at("sock"), "x", 1), HOL_EARG);
    struct stat st;
    assert_int_equal(lstat(at("fifo"), &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_int_equal(lstat(at("sock"), &st), 0);
    assert_true(S_ISSOCK(st.st_mode));
}

/* The number of entries of dir (temporary files included). */
static int count_entries(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "ls -A '%s' | wc -l", dir);
    FILE *p = popen(cmd, "r");
    int n = -1;
    assert_non_null(p);
    assert_int_equal(fscanf(p, "%d", &n), 1);
    pclose(p);
    return n;
}

static void test_commit_raced(void **state)
{
    (void)state;
    const char *kinds[] = {"fifo", "socket", "directory"};
    for (int k = 0; k < 3; k++) {
        char name[32];
        snprintf(name, sizeof name, "raced-%d", k);
        const char *path = at(name);
        int before = count_entries();
        hol_file_atomic a;
        assert_int_equal(hol_file_atomic_open(&a, path), HOL_OK);
        fputs("data\n", a.f);
        /* the target becomes a special file between the check and the rename */
        if (k == 0)
            assert_int_equal(mkfifo(path, 0600), 0);
        else if (k == 1)
            make_socket(path);
        else
            assert_int_equal(mkdir(path, 0700), 0);
        if (hol_file_atomic_commit(&a) != HOL_EARG)
            fail_msg("a %s was replaced", kinds[k]);
        assert_int_equal(errno, EEXIST);
        struct stat st;
        assert_int_equal(lstat(path, &st), 0);
        assert_false(S_ISREG(st.st_mode));
        /* the temporary file is gone: only the special file was added */
        assert_int_equal(count_entries(), before + 1);
    }
    /* a regular file or a new name at the rename: written */
    hol_file_atomic a;
    assert_int_equal(hol_file_atomic_open(&a, at("plain")), HOL_OK);
    fputs("data\n", a.f);
    assert_int_equal(hol_file_atomic_commit(&a), HOL_OK);
    assert_int_equal(hol_file_write_atomic(at("plain"), "new\n", 4), HOL_OK);
    uint8_t *d;
    size_t n;
    assert_int_equal(hol_file_read_all(at("plain"), 100, &d, &n), HOL_OK);
    assert_int_equal(n, 4);
    assert_memory_equal(d, "new\n", 4);
    free(d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_check_out),
        cmocka_unit_test(test_commit_raced),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
