/* files.h — small file-system helpers shared by the libraries. */
#ifndef MPSDEM_CORE_FILES_H
#define MPSDEM_CORE_FILES_H

/* mkdir -p: create dir and its missing parents (mode 0777 less the umask).
 * SIM_ERR_IO naming the directory that could not be made. */
int files_mkdir_p(const char *dir);

#endif
