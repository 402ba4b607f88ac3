!> "Did you mean X?" suggestions: the closest name by edit distance (Levenshtein 1966).
module deck_suggest
    use strings, only: string_t, to_upper
    implicit none
    private
    public :: edit_distance, did_you_mean

contains

    !> Levenshtein distance between a and b (insertions, deletions, substitutions cost 1).
    pure integer function edit_distance(a, b)
        character(len=*), intent(in) :: a, b
        integer :: prev(0:len(b)), cur(0:len(b)), i, j
        do j = 0, len(b)
            prev(j) = j
        end do
        do i = 1, len(a)
            cur(0) = i
            do j = 1, len(b)
                cur(j) = min(prev(j) + 1, cur(j - 1) + 1, &
                             prev(j - 1) + merge(0, 1, a(i:i) == b(j:j)))
            end do
            prev = cur
        end do
        edit_distance = prev(len(b))
    end function edit_distance

    !> ' (did you mean X?)' for the candidate closest to `name` (case-insensitive), when it
    !> is close enough (distance <= max(2, len/3)); '' otherwise.
    function did_you_mean(name, candidates) result(text)
        character(len=*), intent(in) :: name
        type(string_t), intent(in) :: candidates(:)
        character(len=:), allocatable :: text
        integer :: k, d, best, best_k
        text = ''
        best = huge(1); best_k = 0
        do k = 1, size(candidates)
            d = edit_distance(to_upper(name), to_upper(candidates(k)%s))
            if (d < best) then
                best = d; best_k = k
            end if
        end do
        if (best_k == 0) return
        if (best <= max(2, len(name) / 3) .and. best < len(name)) &
            text = ' (did you mean ' // candidates(best_k)%s // '?)'
    end function did_you_mean

end module deck_suggest
