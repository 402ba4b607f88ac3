!> Handlers of the function commands: DEFI_CONSTANTE, DEFI_FONCTION, FORMULE, DEFI_LIST_REEL.
!> They are side-effect free and are registered with at_check, so `parasol --check` finds
!> their errors (non-increasing abscissae, syntax errors inside FORMULE VALE, ...).
module function_commands
    use kinds, only: dp, i4
    use strings, only: string_t, to_text
    use status, only: status_t, add_context
    use deck_value, only: value_t, append_string, append_value
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use constant_function, only: constant_function_t
    use tabulated_function, only: tabulated_function_t, prolongation_code
    use formula_function, only: formula_function_t
    use formula_compiler, only: compile_formula
    use real_list, only: real_list_t
    implicit none
    private

    !> Relative tolerance for PAS dividing an INTERVALLE (a step count must be an integer).
    real(dp), parameter :: STEP_TOLERANCE = 1.0e-6_dp
    !> Most values DEFI_LIST_REEL may generate.
    integer, parameter :: MAX_LIST = 10000000

    public :: run_defi_constante, run_defi_fonction, run_formule, run_defi_list_reel

contains

    !> DEFI_CONSTANTE(VALE=v): a constant function.
    subroutine run_defi_constante(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(constant_function_t), allocatable :: f
        allocate (f)
        call cmd%get_real('VALE', f%value, st)
        if (st%ok()) call cmd%get_text('NOM_RESU', f%result_name, st)
        if (st%failed()) return
        call move_alloc(f, result)
        if (ctx%checking) return
    end subroutine run_defi_constante

    !> DEFI_FONCTION: NOM_PARA, VALE=(x1,y1,...) or ABSCISSE/ORDONNEE, PROL_GAUCHE/DROITE.
    !>  st : abscissae not strictly increasing, odd VALE count, ABSCISSE/ORDONNEE sizes differ
    subroutine run_defi_fonction(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(tabulated_function_t), allocatable :: f
        real(dp), allocatable :: vale(:)
        character(len=:), allocatable :: text, key
        integer :: k, n
        allocate (f)
        call cmd%get_text('NOM_PARA', f%parameter, st)
        if (st%ok()) call cmd%get_text('NOM_RESU', f%result_name, st)
        if (st%failed()) return
        if (cmd%has('VALE')) then
            key = 'VALE'
            call cmd%get_reals('VALE', vale, st)
            if (st%failed()) return
            n = size(vale) / 2
            if (mod(size(vale), 2) /= 0) then
                call cmd%error_at('VALE', 'VALE holds pairs (x1, y1, x2, y2, ...): got an ' // &
                                  'odd count, ' // to_text(int(size(vale), i4)), st); return
            end if
            f%x = vale(1:2 * n - 1:2)
            f%y = vale(2:2 * n:2)
        else
            key = 'ABSCISSE'
            call cmd%get_reals('ABSCISSE', f%x, st)
            if (st%failed()) return
            call cmd%get_reals('ORDONNEE', f%y, st)
            if (st%failed()) return
            if (size(f%x) /= size(f%y)) then
                call cmd%error_at('ORDONNEE', 'ORDONNEE has ' // to_text(int(size(f%y), i4)) &
                    // ' values but ABSCISSE has ' // to_text(int(size(f%x), i4)), st); return
            end if
        end if
        do k = 2, size(f%x)
            if (.not. (f%x(k) > f%x(k - 1))) then
                call cmd%error_at(key, 'abscissae must be strictly increasing: x' // &
                    to_text(int(k, i4)) // ' = ' // to_text(f%x(k)) // ' follows x' // &
                    to_text(int(k - 1, i4)) // ' = ' // to_text(f%x(k - 1)), st); return
            end if
        end do
        call cmd%get_text('PROL_GAUCHE', text, st)
        if (st%failed()) return
        f%left = prolongation_code(text)
        call cmd%get_text('PROL_DROITE', text, st)
        if (st%failed()) return
        f%right = prolongation_code(text)
        call move_alloc(f, result)
        if (ctx%checking) return
    end subroutine run_defi_fonction

    !> FORMULE(NOM_PARA=(...), VALE='expr', NAME=object, ...): compiles VALE once.
    !>  st : syntax error or unknown name, located inside the VALE string
    subroutine run_formule(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(formula_function_t), allocatable :: f
        type(string_t), allocatable :: bound_names(:)
        type(value_t), allocatable :: bound_values(:)
        type(value_t) :: vale
        integer :: k, j, line0, col0
        allocate (f)
        call cmd%get_texts('NOM_PARA', f%params, st)
        if (st%failed()) return
        do k = 2, size(f%params)
            do j = 1, k - 1
                if (f%params(j)%s == f%params(k)%s) then
                    call cmd%error_at('NOM_PARA', 'parameter ' // f%params(k)%s // &
                                      ' is listed twice', st); return
                end if
            end do
        end do
        call cmd%get_text('VALE', f%source, st)
        if (st%failed()) return
        vale = cmd%get_value('VALE')
        call string_start(ctx, vale%line, vale%col, line0, col0)
        allocate (bound_names(0), bound_values(0))
        do k = 1, cmd%n
            if (cmd%items(k)%name == 'VALE' .or. cmd%items(k)%name == 'NOM_PARA') cycle
            call append_string(bound_names, cmd%items(k)%name)
            call append_value(bound_values, cmd%items(k)%value)
        end do
        call compile_formula(ctx, f%source, line0, col0, f%params, bound_names, bound_values, &
                             f%prog, st)
        if (st%failed()) then
            call add_context(st, command='FORMULE', keyword='VALE')
            return
        end if
        call move_alloc(f, result)
    end subroutine run_formule

    !> Position of the first character inside the string literal that starts at (line, col):
    !> after ' or " (col + 1), or after ''' or """ (col + 3).
    subroutine string_start(ctx, line, col, line0, col0)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: line, col
        integer, intent(out) :: line0, col0
        character(len=:), allocatable :: text
        line0 = line; col0 = col + 1
        if (line < 1 .or. line > size(ctx%lines)) return
        text = ctx%lines(line)%s
        if (col + 2 <= len(text) .and. col >= 1) then
            if (text(col:col + 2) == "'''" .or. text(col:col + 2) == '"""') col0 = col + 3
        end if
    end subroutine string_start

    !> DEFI_LIST_REEL: VALE=(...) or DEBUT + INTERVALLE=_F(JUSQU_A, PAS | NOMBRE) repeated.
    !>  st : values not strictly increasing, PAS not dividing an interval, NOMBRE < 1
    subroutine run_defi_list_reel(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(real_list_t), allocatable :: list
        integer :: k
        allocate (list)
        if (cmd%has('VALE')) then
            call cmd%get_reals('VALE', list%values, st)
            if (st%failed()) return
            do k = 2, size(list%values)
                if (.not. (list%values(k) > list%values(k - 1))) then
                    call cmd%error_at('VALE', 'values must be strictly increasing: value ' // &
                        to_text(int(k, i4)) // ' = ' // to_text(list%values(k)) // &
                        ' follows ' // to_text(list%values(k - 1)), st); return
                end if
            end do
        else
            call build_intervals(cmd, list%values, st)
            if (st%failed()) return
        end if
        call move_alloc(list, result)
        if (ctx%checking) return
    end subroutine run_defi_list_reel

    !> DEBUT, then each INTERVALLE up to JUSQU_A by PAS or in NOMBRE equal steps.
    subroutine build_intervals(cmd, values, st)
        type(command_t), intent(in) :: cmd
        real(dp), allocatable, intent(out) :: values(:)
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        real(dp) :: start, finish, step, count
        integer :: i, k, n, nv
        call cmd%get_real('DEBUT', start, st)
        if (st%failed()) return
        allocate (values(1))
        values(1) = start; nv = 1
        do i = 1, cmd%count('INTERVALLE')
            occ = cmd%occurrence('INTERVALLE', i)
            call occ%get_real('JUSQU_A', finish, st)
            if (st%failed()) return
            if (.not. (finish > start)) then
                call occ%error_at('JUSQU_A', 'JUSQU_A = ' // to_text(finish) // ' must be ' // &
                    'greater than the previous end ' // to_text(start) // ' (the list is ' // &
                    'strictly increasing)', st); return
            end if
            if (occ%has('PAS')) then
                call occ%get_real('PAS', step, st)
                if (st%failed()) return
                if (.not. (step > 0.0_dp)) then
                    call occ%error_at('PAS', 'PAS must be positive', st); return
                end if
                ! more than MAX_LIST steps is refused before the division, which a step
                ! of 4.9e-324 (a denormal) would overflow
                if ((finish - start) / real(MAX_LIST, dp) > step) then
                    call occ%error_at('PAS', 'PAS = ' // to_text(step) // ' makes more ' // &
                        'than ' // to_text(int(MAX_LIST, i4)) // ' steps in [' // &
                        to_text(start) // ', ' // to_text(finish) // ']', st); return
                end if
                count = (finish - start) / step
                if (count > real(MAX_LIST, dp) .or. abs(count - anint(count)) > &
                    STEP_TOLERANCE * max(1.0_dp, count)) then
                    call occ%error_at('PAS', 'PAS = ' // to_text(step) // ' does not divide ' // &
                        'the interval [' // to_text(start) // ', ' // to_text(finish) // &
                        '] into a whole number of steps (or use NOMBRE)', st); return
                end if
                n = nint(count)
            else
                call occ%get_int('NOMBRE', n, st)
                if (st%failed()) return
                if (n < 1 .or. n > MAX_LIST) then
                    call occ%error_at('NOMBRE', 'NOMBRE must be between 1 and ' // &
                                      to_text(int(MAX_LIST, i4)), st); return
                end if
            end if
            if (nv + n > MAX_LIST) then
                call occ%error_at('', 'the list would exceed ' // to_text(int(MAX_LIST, i4)) &
                                  // ' values', st); return
            end if
            values = [values, (start + (finish - start) * real(k, dp) / real(n, dp), k = 1, n)]
            values(size(values)) = finish
            nv = size(values)
            start = finish
        end do
    end subroutine build_intervals

end module function_commands
