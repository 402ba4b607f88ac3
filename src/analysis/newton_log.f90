!> The lines STAT_NON_LINE writes about its iterations and steps: a row of the Newton
!> table in the .mess, the terminal line of a finished step, the residual history of a
!> failure (doc/analysis.md, ".mess per step").
module newton_log
    use kinds, only: dp, i4
    use strings, only: to_text, real_short
    use newton_state, only: MATRIX_ELASTIC
    implicit none
    private

    public :: history_text, step_line, seconds_text, iteration_row

contains

    function history_text(values) result(text)
        real(dp), intent(in) :: values(0:)
        character(len=:), allocatable :: text
        integer(i4) :: k
        character(len=12) :: buf
        text = ''
        do k = 0, int(ubound(values, 1), i4)
            write (buf, '(es10.3)') values(k)
            text = text // ' ' // trim(adjustl(buf))
        end do
    end function history_text

    !> The terminal line of a finished step: INST, iterations, residual, springs closed and
    !> changed in the step, factorizations, wall time.
    function step_line(t, step, n_steps, iterations, resi_rela, zero_load, n_closed, &
                       n_changed, n_springs, factorizations, seconds) result(text)
        real(dp), intent(in) :: t, resi_rela, seconds
        integer(i4), intent(in) :: step, n_steps, iterations, n_closed, n_changed, n_springs, &
            factorizations
        logical, intent(in) :: zero_load
        character(len=:), allocatable :: text
        text = 'INST ' // real_short(t) // ' (step ' // to_text(step) // '/' // &
            to_text(n_steps) // '): ' // to_text(iterations) // ' iteration(s), '
        if (zero_load) then
            text = text // 'no load (absolute criterion)'
        else
            text = text // 'RESI_GLOB_RELA ' // real_short(resi_rela)
        end if
        text = text // ', ' // to_text(n_closed) // ' of ' // to_text(n_springs) // &
            ' springs closed (' // to_text(n_changed) // ' changed), ' // &
            to_text(factorizations) // ' factorization(s), ' // seconds_text(seconds) // ' s'
    end function step_line

    !> Seconds with three decimals (the TIME column's precision).
    function seconds_text(seconds) result(text)
        real(dp), intent(in) :: seconds
        character(len=:), allocatable :: text
        character(len=24) :: buf
        write (buf, '(f0.3)') max(seconds, 0.0_dp)
        text = trim(buf)
        if (text(1:1) == '.') text = '0' // text
    end function seconds_text

    !> One row of the Newton table.
    function iteration_row(iter, resi_rela, resi_maxi, zero_load, use, mode, n_closed, &
                           changed, seconds) result(line)
        integer(i4), intent(in) :: iter, use, mode, n_closed, changed
        real(dp), intent(in) :: resi_rela, resi_maxi, seconds
        logical, intent(in) :: zero_load
        character(len=100) :: line
        character(len=22) :: matrix
        character(len=14) :: rela
        character(len=9), parameter :: modes(0:2) = [character(len=9) :: ' reused', &
            ' factored', ' updated']
        matrix = merge('ELASTIQUE', 'TANGENTE ', use == MATRIX_ELASTIC)
        matrix = trim(matrix) // modes(mode)
        write (rela, '(es14.6)') resi_rela
        if (zero_load) rela = '     undefined'
        write (line, '(i5, 2x, a14, 2x, es14.6, 2x, a22, i6, i8, f9.3)') iter, rela, &
            resi_maxi, matrix, n_closed, changed, seconds
    end function iteration_row

end module newton_log
