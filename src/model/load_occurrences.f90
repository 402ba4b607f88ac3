!> Helpers of the load commands (AFFE_CHAR_MECA and its relations) on one occurrence of a
!> factor keyword: recording where the occurrence is, so that an error found when its item
!> is applied (at assembly) names the deck line; reading a vector of up to three reals.
module load_occurrences
    use kinds, only: dp, i4
    use status, only: status_t
    use deck_command, only: keyword_set_t
    use model_loads, only: load_set_t, load_set_location
    implicit none
    private

    public :: locate_item, three_reals

contains

    !> Records where the occurrence of item `index` of `loads` is (file, line, column,
    !> command and factor keyword), for errors found when the item is applied.
    subroutine locate_item(occ, loads, index)
        type(keyword_set_t), intent(in) :: occ
        type(load_set_t), intent(inout) :: loads
        integer(i4), intent(in) :: index
        character(len=:), allocatable :: file
        integer :: line, col
        call occ%location('', file, line, col)
        call load_set_location(loads, index, file, line, col, occ%command, occ%scope)
    end subroutine locate_item

    !> Up to 3 reals of keyword `key` into v, the missing ones 0 (a vector: DIRECTION,
    !> CENTRE, ANGL_NAUT ...).
    subroutine three_reals(occ, key, v, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        real(dp), intent(out) :: v(3)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: given(:)
        v = 0.0_dp
        call occ%get_reals(key, given, st)
        if (st%ok()) v(1:min(3, size(given))) = given(1:min(3, size(given)))
    end subroutine three_reals

end module load_occurrences
