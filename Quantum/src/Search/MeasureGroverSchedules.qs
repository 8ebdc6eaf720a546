namespace QuantumRayTracing.Search {
    /// # Summary
    /// Runs the remaining Grover runs of many searches in one call: each search's runs in order,
    /// stopping after the first run whose measured index is marked.
    ///
    /// # Input
    /// ## requests
    /// One `(count, marked, iterations)` tuple per search: the number of indices, the marked
    /// indices, and the iteration count of each run in the order the search makes them.
    ///
    /// # Output
    /// For each search, the measured index of every run made: up to and including the first
    /// marked one, or all of them when none is marked.
    ///
    /// # Remarks
    /// The runs after the first marked index are the ones the search would never observe, so
    /// leaving them out changes no outcome; the host still verifies every index it receives.
    operation MeasureGroverSchedules(requests : (Int, Int[], Int[])[]) : Int[][] {
        mutable results = [];
        for (count, marked, runs) in requests {
            mutable isMarked = [false, size = count];
            for m in marked {
                if m >= 0 and m < count {
                    set isMarked w/= m <- true;
                }
            }
            mutable measured = [];
            mutable found = false;
            for iterations in runs {
                if not found {
                    let index = MeasureGroverSearch(count, marked, iterations);
                    set measured += [index];
                    // Under noise an index can read past count: it is no hit.
                    set found = index < count and isMarked[index];
                }
            }
            set results += [measured];
        }
        results
    }
}
