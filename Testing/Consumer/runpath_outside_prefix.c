/* A program whose RUNPATH points outside the folder it is in
   (install.runpath_check_can_fail): CheckRunpaths.cmake must refuse it. */
int main(void)
{
  return 0;
}
