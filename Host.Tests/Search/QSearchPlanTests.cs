using QuantumRayTracing.Engines;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Search;

/// <summary>
/// Planning a search's remaining runs (<see cref="QSearch.PlanRemaining"/>) and the driver's one-call path for
/// engines that run whole schedules: the same runs, outcomes and counts as the lock-step rounds.
/// </summary>
public class QSearchPlanTests
{
    /// <summary>Measures a run deterministically from its iteration count, so both driver paths see the same outcomes.</summary>
    private static int Outcome(GroverRequest request) =>
        request.Marked.MarkedCount > 0 && request.Iterations % 3 == 2
            ? request.Marked.Indices[0]
            : Enumerable.Range(0, request.Marked.Count).First(i => !request.Marked.Contains(i));

    [Theory]
    [InlineData(64, new[] { 40 })]
    [InlineData(512, new[] { 3, 300 })]
    [InlineData(64, new int[0])]
    public void ScheduleEngineGivesTheLockStepResults(int count, int[] marked)
    {
        var set = new MarkedSet(count, marked);
        var lockStep = QSearchTests.Searches(set, 200, seed: 5);
        var planned = QSearchTests.Searches(set, 200, seed: 5);
        var lockStepEngine = new RuleEngine();
        var scheduleEngine = new RuleScheduleEngine();

        var rounds = QSearchDriver.Run(lockStep, lockStepEngine);
        Assert.Equal(1, QSearchDriver.Run(planned, scheduleEngine));

        Assert.Equal(1, scheduleEngine.Calls);
        Assert.True(rounds > 1);
        // Each search draws from its own stream, so both paths draw the same r_l and observe the same indices.
        Assert.Equal(lockStep.Select(s => (s.Found, s.LastMeasured, s.Cost)), planned.Select(s => (s.Found, s.LastMeasured, s.Cost)));
        // The schedule engine ran exactly the runs the lock-step driver asked for: none after a search ended.
        Assert.Equal(lockStepEngine.Requests, scheduleEngine.Runs);
    }

    [Fact]
    public void PlanListsEveryRemainingRunInOrder()
    {
        var schedule = new QSearchSchedule(64);
        var search = QSearchTests.Searches(new MarkedSet(64, []), 1, seed: 8)[0];
        var plan = search.PlanRemaining();
        Assert.Equal(schedule.Bounds.Count + 1, plan.Count);
        Assert.Equal(0, plan[0].Iterations);
        for (var l = 1; l < plan.Count; l++) Assert.InRange(plan[l].Iterations, 1, schedule.Bounds[l - 1]);
        // Stage by stage, the search then asks for exactly the planned runs.
        foreach (var run in plan)
        {
            Assert.Equal(run.Iterations, search.NextRequest().Iterations);
            search.Observe(1);
        }
        Assert.True(search.IsDone);
    }

    [Fact]
    public void TooFewOutcomesFailTheDriver()
    {
        var searches = QSearchTests.Searches(new MarkedSet(64, []), 3, seed: 2);
        var engine = new RuleScheduleEngine { DropLast = true };
        Assert.Throws<InvalidOperationException>(() => QSearchDriver.Run(searches, engine));
    }

    private sealed class RuleEngine : IGroverEngine
    {
        public int Requests;
        public string Name => "rule";

        public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
        {
            Requests += requests.Count;
            return requests.Select(Outcome).ToArray();
        }

        public void Dispose() { }
    }

    private sealed class RuleScheduleEngine : IScheduleEngine
    {
        public int Calls, Runs;
        public bool DropLast;
        public string Name => "rule schedules";

        public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests) => throw new InvalidOperationException("schedules only");

        public IReadOnlyList<int[]> MeasureSchedules(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules)
        {
            Calls++;
            return schedules.Select(runs =>
            {
                var outcomes = new List<int>();
                foreach (var run in runs)
                {
                    outcomes.Add(Outcome(run));
                    if (run.Marked.Contains(outcomes[^1])) break;
                }
                Runs += outcomes.Count;
                return DropLast ? outcomes.SkipLast(1).ToArray() : outcomes.ToArray();
            }).ToArray();
        }

        public void Dispose() { }
    }
}
