/* A deliberate data race inside an OpenMP parallel region. The ThreadSanitizer
 * build must report it (exit code 66): the clean runs of check_model_threads
 * and check_pair_threads mean something only if this setup sees a race in an
 * OpenMP region when there is one. */
#include <stdio.h>

int main(void)
{
    long sum = 0;
#pragma omp parallel num_threads(2)
    {
        for (long i = 0; i < 100000; ++i)
            sum += i; /* unsynchronised read-modify-write from both threads */
    }
    printf("race canary: sum = %ld (a clean TSan run here is a broken setup)\n", sum);
    return 0;
}
