#include "demCouplingWeights.H"
#include "demParallel.H"

template<class Type>
Foam::List<Type> Foam::demCouplingWeights::average
(
    const UList<Type>& cellValues
) const
{
    List<Type> result(cell_.size(), Zero);
    forAll(cell_, i)
    {
        for (label k = start_[i]; k < start_[i + 1]; ++k)
        {
            result[i] += weight_[k]*cellValues[cellIndex_[k]];
        }
    }
    demParallel::allSum(result);
    return result;
}
