!> IMPR_FONCTION (U4.33.01): functions written for a curve plotter, as Code_Aster's
!> impr_fonction_ops builds its graph of curves and its TraceTableau / TraceAgraf write it.
!>
!> Curves (COURBE): FONCTION (a function's points; a FORMULE needs LIST_PARA), LIST_RESU on
!> LIST_PARA, FONC_X / FONC_Y (a parametric curve), ABSCISSE / ORDONNEE; LIST_PARA
!> interpolates a function on its values. A curve's columns are named as Code_Aster names
!> them: a function's NOM_PARA and NOM_RESU_<k> (k: the curve's rank from 0), a list's
!> concept names, 'Absc' and 'Ordo'; its legend is LEGENDE, else the concept's name.
!>
!> FORMAT='TABLEAU' (default unit 8, the .resu): every function is interpolated on one list
!> of abscissae (the first curve's LIST_PARA, else its abscissae; a curve that cannot be,
!> outside an EXCLU range, is left out with a warning, as Code_Aster leaves it out), then
!> written as a table (IMPR_TABLE's layout, table_listing) whose title lines are
!> `<COMMENTAIRE> <title line>`, the SOUS_TITRE, `Courbe <k>` and each legend (the table
!> layout adds COMMENTAIRE again: `## Courbe 0`, as Code_Aster prints them); FORMAT_R,
!> SEPARATEUR, COMMENTAIRE, COMM_PARA, DEBUT_LIGNE, FIN_LIGNE as IMPR_TABLE's.
!> FORMAT='AGRAF': the values on UNITE (default 25), a block per curve
!> (`#NOM DE LA FONCTION: <legend>`, then ` %12.5E` per value), and the plotter's
!> directives on UNITE_DIGR (default 26): Code_Aster's fixed header (ASPECT_GRAPHIQUE, the
!> twelve DEFAUT_COURBE colours), the graph (title, grids, scales, axis legends,
!> bounds: BORNE_X/Y or the values' extent widened by 5 %) and each curve (style, colour,
!> marker cycling with the curve's rank as Code_Aster's ValCycl, legend, TRI, its block and
!> columns). FORMAT XMGRACE and LISS_ENVELOP (plots) are not written by parasol.
module impr_fonction_command
    use kinds, only: dp, i4
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use python_format, only: float_repr, parse_real_format, format_real, real_format_t
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use deck_value, only: append_string
    use run_context, only: run_context_t
    use function_concept, only: function_concept_t
    use formula_function, only: formula_function_t
    use real_list, only: real_list_t
    use function_points, only: function_samples_t, samples_of_function
    use function_algebra, only: function_value_at
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_set_real, TABLE_REAL
    use table_keywords, only: relocate_at, warn_at
    use table_listing, only: table_layout_t, default_table_layout, table_text_lines
    use unit_text_output, only: write_unit_text
    implicit none
    private

    !> Code_Aster's default units: TABLEAU 8 (the .resu), AGRAF 25 (values), 26 (directives).
    integer, parameter :: TABLEAU_UNIT = 8, AGRAF_UNIT = 25

    !> One curve of the graph.
    type :: curve_t
        character(len=:), allocatable :: legend, x_label, y_label
        real(dp), allocatable :: x(:), y(:)
        integer :: style = -1, colour = -1, marker = -1, marker_frequency = 0
        character(len=:), allocatable :: sort
    end type curve_t

    public :: run_impr_fonction

contains

    !> Handler of IMPR_FONCTION.
    subroutine run_impr_fonction(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(curve_t), allocatable :: curves(:)
        character(len=:), allocatable :: format
        real(dp), allocatable :: common(:)
        logical :: interpolate
        if (allocated(result)) deallocate (result)
        call cmd%get_text('FORMAT', format, st)
        if (st%failed()) return
        if (format == 'XMGRACE' .or. format == 'LISS_ENVELOP') then
            call cmd%error_at('FORMAT', 'FORMAT=''' // format // ''' (a plot) is not written ' // &
                'by parasol (TABLEAU and AGRAF are)', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        interpolate = format == 'TABLEAU'
        if (interpolate) call common_abscissae(cmd, common, st)
        if (st%failed()) return
        call build_curves(ctx, cmd, interpolate, common, curves, st)
        if (st%failed()) return
        if (format == 'TABLEAU') then
            call write_tableau(ctx, cmd, curves, st)
        else
            call write_agraf(ctx, cmd, curves, st)
        end if
    end subroutine run_impr_fonction

    !> TABLEAU: the abscissae every curve is interpolated on: LIST_PARA of the first
    !> occurrence that has one, else the first curve's abscissae.
    subroutine common_abscissae(cmd, x, st)
        type(command_t), intent(in) :: cmd
        real(dp), allocatable, intent(out) :: x(:)
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        class(concept_t), pointer :: c
        type(function_samples_t) :: s
        integer :: k
        allocate (x(0))
        do k = 1, cmd%count('COURBE')
            occ = cmd%occurrence('COURBE', k)
            if (.not. occ%has('LIST_PARA')) cycle
            call list_values(occ, 'LIST_PARA', x, st)
            return
        end do
        occ = cmd%occurrence('COURBE', 1)
        if (occ%has('ABSCISSE')) then
            call occ%get_reals('ABSCISSE', x, st)
        else if (occ%has('FONCTION') .or. occ%has('FONC_X')) then
            call occ%get_concept(trim(merge('FONCTION', 'FONC_X  ', occ%has('FONCTION'))), c, st)
            if (st%failed()) return
            call samples_of_function(c, s, st)
            if (st%failed()) then
                call occ%error_at(trim(merge('FONCTION', 'FONC_X  ', occ%has('FONCTION'))), &
                    st%message // ': give LIST_PARA, the abscissae to print it at', st)
                return
            end if
            x = s%x
            if (occ%has('FONC_X')) x = s%y
        else
            call occ%error_at('LIST_RESU', 'LIST_RESU needs LIST_PARA', st)
        end if
    end subroutine common_abscissae

    !> The values of a listr8 concept at `key`.
    subroutine list_values(occ, key, x, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        real(dp), allocatable, intent(out) :: x(:)
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: c
        allocate (x(0))
        call occ%get_concept(key, c, st)
        if (st%failed()) return
        select type (c)
        type is (real_list_t)
            x = c%values
        class default
            call occ%error_at(key, 'expected a list of reals (DEFI_LIST_REEL)', st)
        end select
    end subroutine list_values

    !> The curves of the COURBE occurrences.
    subroutine build_curves(ctx, cmd, interpolate, common, curves, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        logical, intent(in) :: interpolate
        real(dp), intent(in) :: common(:)
        type(curve_t), allocatable, intent(out) :: curves(:)
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        type(curve_t) :: curve
        type(curve_t), allocatable :: bigger(:)
        logical :: keep
        integer :: k, n
        allocate (curves(0))
        do k = 1, cmd%count('COURBE')
            occ = cmd%occurrence('COURBE', k)
            n = size(curves)
            call one_curve(ctx, occ, k, n, interpolate, common, curve, keep, st)
            if (st%failed()) return
            if (.not. keep) cycle
            allocate (bigger(n + 1))
            bigger(1:n) = curves
            bigger(n + 1) = curve
            call move_alloc(bigger, curves)
        end do
    end subroutine build_curves

    !> One curve; `keep` false when its function cannot be interpolated on the common list.
    subroutine one_curve(ctx, occ, rank, n_before, interpolate, common, curve, keep, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        integer, intent(in) :: rank, n_before
        logical, intent(in) :: interpolate
        real(dp), intent(in) :: common(:)
        type(curve_t), intent(out) :: curve
        logical, intent(out) :: keep
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: c, cy
        type(function_samples_t) :: s
        real(dp), allocatable :: at(:), t(:)
        type(status_t) :: failed
        keep = .true.
        curve%legend = ''
        if (occ%has('LEGENDE')) call occ%get_text('LEGENDE', curve%legend, st)
        call curve_style(occ, curve, st)
        if (st%failed()) return
        if (occ%has('FONCTION')) then
            call occ%get_concept('FONCTION', c, st)
            if (st%failed()) return
            if (.not. occ%has('LEGENDE')) curve%legend = concept_display_name(c)
            call function_labels(c, n_before, curve%x_label, curve%y_label)
            if (interpolate) then
                at = common
            else if (occ%has('LIST_PARA')) then
                call list_values(occ, 'LIST_PARA', at, st)
                if (st%failed()) return
            else
                call samples_of_function(c, s, st)
                if (st%failed()) then
                    call occ%error_at('FONCTION', st%message // ': give LIST_PARA, the ' // &
                        'abscissae to print it at', st)
                    return
                end if
                curve%x = s%x
                curve%y = s%y
                return
            end if
            curve%x = at
            call values_at(c, at, curve%y, failed)
            if (failed%failed()) then
                if (.not. interpolate) then
                    st = failed
                    call relocate_at(occ, 'LIST_PARA', st)
                    return
                end if
                keep = .false.
                call warn_at(ctx, occ, 'FONCTION', 'curve ' // to_text(int(rank, i4)) // &
                    ' is left out: ' // failed%message)
            end if
        else if (occ%has('LIST_RESU')) then
            if (interpolate .and. rank > 1) then
                call occ%error_at('LIST_RESU', 'with FORMAT=''TABLEAU'' a list of values ' // &
                    'can only be the first curve (the others are interpolated on its ' // &
                    'abscissae)', st)
                return
            end if
            if (.not. occ%has('LIST_PARA')) then
                call occ%error_at('LIST_RESU', 'LIST_RESU needs LIST_PARA, its abscissae', st)
                return
            end if
            call list_values(occ, 'LIST_PARA', curve%x, st)
            if (st%ok()) call list_values(occ, 'LIST_RESU', curve%y, st)
            if (st%failed()) return
            if (size(curve%x) /= size(curve%y)) then
                call occ%error_at('LIST_RESU', 'LIST_RESU has ' // &
                    to_text(size(curve%y, kind=i4)) // ' values, LIST_PARA ' // &
                    to_text(size(curve%x, kind=i4)), st)
                return
            end if
            call occ%get_concept('LIST_PARA', c, st)
            call occ%get_concept('LIST_RESU', cy, st)
            curve%x_label = concept_display_name(c)
            curve%y_label = concept_display_name(cy)
            if (.not. occ%has('LEGENDE')) curve%legend = concept_display_name(cy)
        else if (occ%has('FONC_X')) then
            if (interpolate .and. rank > 1) then
                call occ%error_at('FONC_X', 'with FORMAT=''TABLEAU'' a parametric curve ' // &
                    'can only be the first curve', st)
                return
            end if
            call occ%get_concept('FONC_X', c, st)
            if (st%ok() .and. .not. occ%has('FONC_Y')) call occ%error_at('FONC_X', &
                'FONC_X needs FONC_Y', st)
            if (st%ok()) call occ%get_concept('FONC_Y', cy, st)
            if (st%failed()) return
            if (.not. occ%has('LEGENDE')) curve%legend = concept_display_name(c)
            if (occ%has('LIST_PARA')) then
                call list_values(occ, 'LIST_PARA', t, st)
                if (st%failed()) return
                call values_at(c, t, curve%x, st)
            else
                call samples_of_function(c, s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'FONC_X', st)
                    return
                end if
                t = s%x
                curve%x = s%y
            end if
            if (st%ok()) call values_at(cy, t, curve%y, st)
            if (st%failed()) then
                call relocate_at(occ, 'FONC_Y', st)
                return
            end if
            ! Code_Aster's labels of a parametric curve: both NOM_RESU with their ranks
            curve%x_label = result_label(c, n_before)
            curve%y_label = result_label(cy, n_before + 1)
        else
            call occ%get_reals('ABSCISSE', curve%x, st)
            if (st%ok() .and. .not. occ%has('ORDONNEE')) call occ%error_at('ABSCISSE', &
                'ABSCISSE needs ORDONNEE', st)
            if (st%ok()) call occ%get_reals('ORDONNEE', curve%y, st)
            if (st%failed()) return
            if (size(curve%x) /= size(curve%y)) then
                call occ%error_at('ORDONNEE', 'ORDONNEE has ' // &
                    to_text(size(curve%y, kind=i4)) // ' values, ABSCISSE ' // &
                    to_text(size(curve%x, kind=i4)), st)
                return
            end if
            curve%x_label = 'Absc'
            curve%y_label = 'Ordo'
        end if
    end subroutine one_curve

    !> STYLE, COULEUR, MARQUEUR, FREQ_MARQUEUR, TRI of an occurrence (-1: not given).
    subroutine curve_style(occ, curve, st)
        type(keyword_set_t), intent(in) :: occ
        type(curve_t), intent(inout) :: curve
        type(status_t), intent(inout) :: st
        if (occ%has('STYLE')) call occ%get_int('STYLE', curve%style, st)
        if (st%ok() .and. occ%has('COULEUR')) call occ%get_int('COULEUR', curve%colour, st)
        if (st%ok() .and. occ%has('MARQUEUR')) call occ%get_int('MARQUEUR', curve%marker, st)
        if (st%ok()) call occ%get_int('FREQ_MARQUEUR', curve%marker_frequency, st)
        if (st%ok()) call occ%get_text('TRI', curve%sort, st)
    end subroutine curve_style

    !> A function curve's labels: NOM_PARA and NOM_RESU_<rank>.
    subroutine function_labels(c, rank, x_label, y_label)
        class(concept_t), intent(in) :: c
        integer, intent(in) :: rank
        character(len=:), allocatable, intent(out) :: x_label, y_label
        type(string_t), allocatable :: names(:)
        x_label = 'TOUTPARA'
        select type (c)
        class is (function_concept_t)
            names = c%parameters()
            if (size(names) > 0) x_label = names(1)%s
        end select
        y_label = result_label(c, rank)
    end subroutine function_labels

    !> NOM_RESU_<rank> of a function.
    function result_label(c, rank) result(label)
        class(concept_t), intent(in) :: c
        integer, intent(in) :: rank
        character(len=:), allocatable :: label
        type(function_samples_t) :: s
        type(status_t) :: st
        label = 'TOUTRESU'
        call samples_of_function(c, s, st)
        if (st%ok()) label = s%result_name
        label = label // '_' // to_text(int(rank, i4))
    end function result_label

    !> A function's values at the abscissae `x` (function_value_at: Code_Aster's Python
    !> evaluation).
    subroutine values_at(c, x, y, st)
        class(concept_t), intent(in) :: c
        real(dp), intent(in) :: x(:)
        real(dp), allocatable, intent(out) :: y(:)
        type(status_t), intent(inout) :: st
        integer :: k
        allocate (y(size(x)), source=0.0_dp)
        do k = 1, size(x)
            call function_value_at(c, x(k), y(k), st)
            if (st%failed()) return
        end do
    end subroutine values_at

    ! ---- TABLEAU ---------------------------------------------------------------------

    !> The curves as one table on the common abscissae.
    subroutine write_tableau(ctx, cmd, curves, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(curve_t), intent(in) :: curves(:)
        type(status_t), intent(inout) :: st
        type(table_t) :: t
        type(table_layout_t) :: layout
        type(string_t), allocatable :: title(:), lines(:)
        character(len=:), allocatable :: text, comment, where
        integer :: k, j, c, unit
        integer, allocatable :: columns(:)
        call table_init(t)
        allocate (columns(size(curves)))
        if (size(curves) > 0) then
            call table_add_column(t, curves(1)%x_label, TABLE_REAL, c, st)
            call table_add_rows(t, size(curves(1)%x))
            do j = 1, size(curves(1)%x)
                call table_set_real(t, c, j, curves(1)%x(j), st)
            end do
        end if
        do k = 1, size(curves)
            if (st%failed()) exit
            call table_add_column(t, curves(k)%y_label, TABLE_REAL, columns(k), st)
            do j = 1, min(size(curves(k)%y), t%n_rows)
                if (st%ok()) call table_set_real(t, columns(k), j, curves(k)%y(j), st)
            end do
        end do
        if (st%failed()) then
            call relocate_at(cmd, 'COURBE', st)
            return
        end if
        call layout_of(cmd, layout, st)
        if (st%failed()) return
        comment = layout%comment
        allocate (title(0))
        text = ''
        if (cmd%has('TITRE')) call cmd%get_text('TITRE', text, st)
        call append_string(title, comment // ' ' // text)
        text = ''
        if (cmd%has('SOUS_TITRE')) call cmd%get_text('SOUS_TITRE', text, st)
        call append_string(title, comment // ' ' // text)
        do k = 1, size(curves)
            call append_string(title, comment // ' Courbe ' // to_text(int(k - 1, i4)))
            call append_string(title, comment // ' ' // curves(k)%legend)
        end do
        call table_text_lines(t, [(c, c=1, t%n_columns)], [(j, j=1, t%n_rows)], title, &
                              layout, lines)
        unit = TABLEAU_UNIT
        if (cmd%has('UNITE')) call cmd%get_int('UNITE', unit, st)
        if (st%failed()) return
        call write_unit_text(ctx, unit, lines, where, st, cmd, 'UNITE')
        if (st%failed()) return
        call ctx%write_mess('    IMPR_FONCTION: ' // to_text(size(curves, kind=i4)) // &
            ' curve(s), FORMAT TABLEAU -> ' // where)
    end subroutine write_tableau

    !> IMPR_FONCTION's layout keywords (IMPR_TABLE's defaults).
    subroutine layout_of(cmd, layout, st)
        type(command_t), intent(in) :: cmd
        type(table_layout_t), intent(out) :: layout
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        layout = default_table_layout()
        call cmd%get_text('FORMAT_R', text, st)
        if (st%ok()) call parse_real_format(text, layout%real_format, st)
        if (st%failed()) then
            call relocate_at(cmd, 'FORMAT_R', st)
            return
        end if
        if (cmd%has('SEPARATEUR')) call cmd%get_text('SEPARATEUR', layout%separator, st)
        if (st%ok()) call cmd%get_text('COMMENTAIRE', layout%comment, st)
        if (st%ok() .and. cmd%has('COMM_PARA')) &
            call cmd%get_text('COMM_PARA', layout%names_prefix, st)
        if (st%ok() .and. cmd%has('DEBUT_LIGNE')) &
            call cmd%get_text('DEBUT_LIGNE', layout%line_start, st)
        if (st%ok() .and. cmd%has('FIN_LIGNE')) call cmd%get_text('FIN_LIGNE', layout%line_end, st)
    end subroutine layout_of

    ! ---- AGRAF -------------------------------------------------------------------------

    !> The values file and the directives file.
    subroutine write_agraf(ctx, cmd, curves, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(curve_t), intent(in) :: curves(:)
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: values(:), directives(:)
        type(real_format_t) :: e12
        character(len=:), allocatable :: line, where, where_digr
        integer :: k, j, unit, unit_digr
        call parse_real_format('E12.5', e12, st)
        allocate (values(0))
        do k = 1, size(curves)
            if (len(curves(k)%legend) > 0) then
                call append_string(values, '#NOM DE LA FONCTION: ' // curves(k)%legend)
            else
                call append_string(values, '#NOM DE LA FONCTION: COURBE_' // &
                                   to_text(int(k - 1, i4)))
            end if
            do j = 1, size(curves(k)%x)
                line = ' ' // format_real(e12, curves(k)%x(j)) // ' ' // &
                    format_real(e12, curves(k)%y(j))
                call append_string(values, line)
            end do
            call append_string(values, '')
        end do
        call agraf_directives(cmd, curves, directives, st)
        if (st%failed()) return
        unit = AGRAF_UNIT
        if (cmd%has('UNITE')) call cmd%get_int('UNITE', unit, st)
        if (st%ok()) call cmd%get_int('UNITE_DIGR', unit_digr, st)
        if (st%failed()) return
        call write_unit_text(ctx, unit, values, where, st, cmd, 'UNITE')
        if (st%ok()) call write_unit_text(ctx, unit_digr, directives, where_digr, st, cmd, &
                                          'UNITE_DIGR')
        if (st%failed()) return
        call ctx%write_mess('    IMPR_FONCTION: ' // to_text(size(curves, kind=i4)) // &
            ' curve(s), FORMAT AGRAF -> ' // where // ' (directives ' // where_digr // ')')
    end subroutine write_agraf

    !> The directives of the Agraf plotter: the graph, then each curve.
    subroutine agraf_directives(cmd, curves, lines, st)
        type(command_t), intent(in) :: cmd
        type(curve_t), intent(in) :: curves(:)
        type(string_t), allocatable, intent(out) :: lines(:)
        type(status_t), intent(inout) :: st
        real(dp) :: bounds(4), grid(2), low, high, span
        real(dp), allocatable :: given(:)
        character(len=:), allocatable :: text, scale_x, scale_y
        integer :: k, axis
        character(len=*), parameter :: COLOURS(12) = [character(len=17) :: &
            '    0     0     0', '65535     0     0', '11822 35723 22359', &
            '    0     0 65535', '65535     0 65535', '    0 65535 65535', &
            '    0 65535     0', '41120 21074 11565', '65535 42405     0', &
            '41120  8224 61680', '65535 65535     0', '53970 46260 35980']
        allocate (lines(0))
        call append_string(lines, '')
        call append_string(lines, 'ASPECT_GRAPHIQUE:')
        call append_string(lines, '  En-tete :Departement Analyses Mecaniques et Acoustique')
        call append_string(lines, '  Aspect :0')
        call append_string(lines, '  Nombre de vues :1')
        call append_string(lines, '  Cesure commentaire :40')
        call append_string(lines, '  MinMax :0')
        call append_string(lines, '  Fonte Titre :%helvetica-14')
        call append_string(lines, '  Fonte Axes :%courier-12')
        call append_string(lines, '  Fonte Autre :%times-12')
        do k = 1, size(COLOURS)
            call append_string(lines, '')
            call append_string(lines, '  DEFAUT_COURBE:')
            call append_string(lines, '    Couleur (rvb) : ' // COLOURS(k))
        end do
        call append_string(lines, '')
        call append_string(lines, 'GRAPHIQUE:')
        text = ''
        if (cmd%has('TITRE')) call cmd%get_text('TITRE', text, st)
        call append_string(lines, 'Titre :' // text)
        if (cmd%has('SOUS_TITRE')) then
            call cmd%get_text('SOUS_TITRE', text, st)
            call append_string(lines, 'Commentaire :' // text)
        end if
        grid = 0.0_dp                       ! no grid unless both are given
        if (cmd%has('GRILLE_X') .and. cmd%has('GRILLE_Y')) then
            call cmd%get_real('GRILLE_X', grid(1), st)
            call cmd%get_real('GRILLE_Y', grid(2), st)
        end if
        call append_string(lines, 'Frequence Grille X :' // to_text(int(grid(1), i4)))
        call append_string(lines, 'Frequence Grille Y :' // to_text(int(grid(2), i4)))
        call cmd%get_text('ECHELLE_X', scale_x, st)
        call cmd%get_text('ECHELLE_Y', scale_y, st)
        if (st%failed()) return
        call append_string(lines, 'Echelle X :' // trim(merge('1', '0', scale_x == 'LOG')))
        call append_string(lines, 'Echelle Y :' // trim(merge('1', '0', scale_y == 'LOG')))
        if (cmd%has('LEGENDE_X')) then
            call cmd%get_text('LEGENDE_X', text, st)
            call append_string(lines, 'Legende X :' // text)
        end if
        if (cmd%has('LEGENDE_Y')) then
            call cmd%get_text('LEGENDE_Y', text, st)
            call append_string(lines, 'Legende Y :' // text)
        end if
        ! bounds: BORNE_X/Y, else the values' extent widened by 5 % (Code_Aster's marge)
        do axis = 1, 2
            low = huge(1.0_dp)
            high = -huge(1.0_dp)
            do k = 1, size(curves)
                if (axis == 1 .and. size(curves(k)%x) > 0) then
                    low = min(low, minval(curves(k)%x))
                    high = max(high, maxval(curves(k)%x))
                else if (axis == 2 .and. size(curves(k)%y) > 0) then
                    low = min(low, minval(curves(k)%y))
                    high = max(high, maxval(curves(k)%y))
                end if
            end do
            if (low > high) then
                low = 0.0_dp
                high = 0.0_dp
            end if
            ! half the extent (at least 0.5 % of the largest value; 1e-6 when 0), halved
            ! first so that nothing overflows; the bounds stay within the doubles
            span = max(0.5_dp * high - 0.5_dp * low, 0.005_dp * high)
            if (.not. abs(span) > 0.0_dp) span = 0.5e-6_dp
            bounds(2 * axis - 1) = low - min(0.05_dp * span, room_below(low))
            bounds(2 * axis) = high + min(0.05_dp * span, room_below(-high))
            if (cmd%has(trim(merge('BORNE_X', 'BORNE_Y', axis == 1)))) then
                call cmd%get_reals(trim(merge('BORNE_X', 'BORNE_Y', axis == 1)), given, st)
                if (st%failed()) return
                if (.not. given(1) > given(2)) bounds(2 * axis - 1:2 * axis) = given
            end if
        end do
        call append_string(lines, 'Min X : ' // float_repr(bounds(1)))
        call append_string(lines, 'Max X : ' // float_repr(bounds(2)))
        call append_string(lines, 'Min Y : ' // float_repr(bounds(3)))
        call append_string(lines, 'Max Y : ' // float_repr(bounds(4)))
        do k = 1, size(curves)
            call append_string(lines, '  COURBE:')
            call append_string(lines, '     Trait :' // cycled(curves(k)%style, 0, 2, 0))
            call append_string(lines, '     Couleur :' // cycled(curves(k)%colour, 0, 12, k - 1))
            call append_string(lines, '     Marqueur :' // cycled(curves(k)%marker, 0, 12, k - 1))
            call append_string(lines, '     Frequence Marqueur :' // &
                cycled(curves(k)%marker_frequency, 0, -1, 0))
            if (len(curves(k)%legend) > 0) &
                call append_string(lines, '     Legende :' // curves(k)%legend)
            call append_string(lines, '     Tri :' // curves(k)%sort)
            call append_string(lines, '     Abscisses : [ ' // to_text(int(k, i4)) // ', 1]')
            call append_string(lines, '     Ordonnees : [ ' // to_text(int(k, i4)) // ', 2]')
        end do
    end subroutine agraf_directives

    !> How far below x the doubles go (formed without overflow).
    pure real(dp) function room_below(x)
        real(dp), intent(in) :: x
        room_below = huge(1.0_dp)
        if (x < 0.0_dp) room_below = x + huge(1.0_dp)
    end function room_below

    !> A style number in [low, high], cycling, `default` when not given (Code_Aster's
    !> ValCycl; high < low: no upper bound).
    function cycled(value, low, high, default) result(text)
        integer, intent(in) :: value, low, high, default
        character(len=:), allocatable :: text
        integer :: v
        v = value
        if (v < low) v = default
        if (high >= low) v = modulo(v - low, high + 1 - low) + low
        text = to_text(int(v, i4))
    end function cycled

end module impr_fonction_command
